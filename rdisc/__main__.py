"""`python -m rdisc`: the `rdisc` command, through the one entry that holds signals back first
(`rdisc.start`)."""

import sys

from rdisc.start import main

sys.exit(main())
