"""chaindrive.kinematics (see module docs)."""
