"""chaindrive.vibration (see module docs)."""
