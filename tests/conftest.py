"""Shared pytest setup. Each test folder (runtime/, rules/, cli/, typing/, integrations/) owns its own conftest."""
