"""Subcommands of the ``rotarykiln`` CLI, one module each (see :mod:`rotarykiln.cli`)."""
