import sys

from rdisc.cli.main import main

sys.exit(main())
