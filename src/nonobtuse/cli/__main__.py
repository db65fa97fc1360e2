"""``python -m nonobtuse.cli``: the ``nonobtuse`` command."""

import sys

from nonobtuse.cli import main

sys.exit(main())
