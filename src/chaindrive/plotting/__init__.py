"""chaindrive.plotting (see module docs)."""
