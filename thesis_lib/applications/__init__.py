"""The thesis's applications of persistence to real data: protein structures (§2.4.2) and natural
range-image patches (§2.4.3)."""
