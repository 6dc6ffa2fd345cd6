"""GEO9xx: problems with geolint's own suppression comments (detected by the engine, documented here)."""
