#!/usr/bin/env python3
"""JPEG CompressedImage -> raw Image for rviz (Debian has no compressed_image_transport)."""
from exp_assignment2.nodes.image_decompress import main
from exp_assignment2.ros.ending import run_until_shutdown

run_until_shutdown(main)
