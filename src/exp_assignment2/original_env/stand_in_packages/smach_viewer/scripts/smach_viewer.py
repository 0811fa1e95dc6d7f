#!/usr/bin/python3
"""smach_viewer: the running state machines and their active states, or one line without a display."""
import os
import sys

# exp_assignment2's stand-in (src/exp_assignment2/original_env/stand_in_packages/README.md): tools/run
# original-env copies it into the workspace and exports EXP2_REPO, whose src/ holds the
# library. src/ replaces this file's folder on sys.path (xacro.py there shadows xacro).
sys.path[0] = os.path.join(os.environ.get('EXP2_REPO') or os.path.join(
    os.path.dirname(os.path.realpath(__file__)), *['..'] * 6), 'src')
from exp_assignment2.launch_surface.smach_view import main  # noqa: E402

sys.exit(main())
