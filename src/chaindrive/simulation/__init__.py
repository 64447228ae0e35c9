"""chaindrive.simulation (see module docs)."""
