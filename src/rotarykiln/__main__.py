import sys

from rotarykiln.cli import main

sys.exit(main())
