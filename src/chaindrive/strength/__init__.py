"""chaindrive.strength (see module docs)."""
