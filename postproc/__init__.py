"""tapegate package."""
