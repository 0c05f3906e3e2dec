"""``python -m tapegate``: the same as the ``tapegate`` command."""

from tapegate.cli import main

main(prog_name="tapegate")
