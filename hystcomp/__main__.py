"""``python -m hystcomp``: the ``hystcomp`` console command (:mod:`hystcomp.cli`)."""

import sys

from .cli import main

if __name__ == "__main__":
    sys.exit(main())
