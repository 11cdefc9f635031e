"""`python3 -m ros2vtk_gen`."""
import sys

from .cli import main

sys.exit(main())
