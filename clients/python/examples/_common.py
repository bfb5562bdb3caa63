"""What the examples share: the package on the path and the connection options."""

import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

from sph_client import Endpoints  # noqa: E402


def parser(description: str) -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description=description)
    Endpoints.add_arguments(p)
    p.add_argument("--curve-secret", help="this client's certificate, PATH.key_secret (CURVE servers)")
    p.add_argument("--curve-server", help="the server's public certificate, PATH.key")
    return p


def security(args) -> dict:
    return {"curve_secret": args.curve_secret, "curve_server": args.curve_server}
