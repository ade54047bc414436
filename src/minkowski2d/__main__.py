"""``python -m minkowski2d``: the same command as ``minkowski2d``."""

import sys

from .cli import main

sys.exit(main())
