#!/usr/bin/python3
"""sph_load: a load generator for sph_server (clients/python/README.md). Run it with Debian's
interpreter, /usr/bin/python3, which has python3-zmq, python3-protobuf and python3-numpy."""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from sph_client.load.cli import main  # noqa: E402  (the path above comes first)

if __name__ == "__main__":
    sys.exit(main())
