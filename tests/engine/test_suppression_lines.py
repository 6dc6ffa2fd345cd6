"""Own-line suppressions count lines the way the engine does: a form feed is not a line break."""

from geolint.api import lint_text

FLAGGED = "normal_world = R_world_cam @ normal_cam + t_world_cam\n"


def test_own_line_directive_after_a_form_feed_covers_the_next_statement() -> None:
    source = "x = 1\n\x0c\n# geolint: ignore[GEO101]\n" + FLAGGED
    assert [f.code for f in lint_text("x = 1\n\x0c\n" + FLAGGED)] == ["GEO101"]
    assert lint_text(source) == []
