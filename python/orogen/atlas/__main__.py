"""`python3 -m orogen.atlas DIR [--out SITE]`: what `orogen report` runs."""
import sys

from .cli import main

sys.exit(main())
