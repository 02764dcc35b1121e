"""``python -m hystcomp.diagnose DATA.csv ...`` (the same as ``hystcomp diagnose``)."""

import sys

from .cli import main

sys.exit(main())
