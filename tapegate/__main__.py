"""``python -m tapegate``: the same as the ``tapegate`` command."""

from tapegate.launch import main

main(prog_name="tapegate")
