"""``python -m rocking.cli``: the ``rocking`` command."""

from . import main

main()
