"""Workflows on top of the core: demo, analysis pipeline, reports."""
