"""GEO0xx: problems reading the file itself (detected by the engine, documented here)."""
