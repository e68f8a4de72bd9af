"""``python -m contact`` runs the ``ltca`` command line."""

import sys

from contact.cli import main

sys.exit(main())
