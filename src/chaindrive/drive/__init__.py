"""chaindrive.drive (see module docs)."""
