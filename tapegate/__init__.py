"""The ``tapegate`` command line: options in, library calls, results out."""
