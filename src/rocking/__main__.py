"""``python -m rocking``: the ``rocking`` command (:func:`rocking.cli.main`), for an
environment where the console script is not on ``PATH``."""

from .cli import main

if __name__ == "__main__":
    main()
