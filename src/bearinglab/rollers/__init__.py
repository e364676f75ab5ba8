"""Roller bearings (placeholder, filled below)."""
