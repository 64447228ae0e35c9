"""Analysis steps (filled in as the topic modules land)."""
