"""chaindrive.chains (see module docs)."""
