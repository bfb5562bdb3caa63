"""The generated protobuf module for proto/sph.proto (package gsph.v1), found or made on first import.

The generated code is not committed: it would go stale the moment someone edits sph.proto, and it
must match the installed python3-protobuf. Where it comes from, first match wins:

1. ``$SPH_PB2_DIR``: a folder holding ``sph_pb2.py`` (the CMake build writes one into
   ``build/clients/python/generated``; the ctest entries point here).
2. A cache folder keyed by the schema's hash, filled by running ``protoc`` once on the schema that
   ships beside this file (``sph.proto``, a link to ``proto/sph.proto`` in the repository, copied
   into wheels). ``$SPH_PROTOC`` names the compiler, default ``protoc`` on PATH.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from types import ModuleType

_MODULE_NAME = "sph_pb2"


def schema_path() -> Path:
    """The sph.proto this package was built from (env SPH_PROTO_FILE overrides)."""
    override = os.environ.get("SPH_PROTO_FILE")
    if override:
        return Path(override)
    here = Path(__file__).resolve().parent
    for candidate in (here / "sph.proto", here.parent.parent.parent / "proto" / "sph.proto"):
        if candidate.is_file():
            return candidate
    raise ImportError("sph_client: no sph.proto found (set SPH_PROTO_FILE or SPH_PB2_DIR)")


def _load_from(folder: Path) -> ModuleType:
    path = folder / f"{_MODULE_NAME}.py"
    spec = importlib.util.spec_from_file_location(_MODULE_NAME, path)
    if spec is None or spec.loader is None:
        raise ImportError(f"sph_client: cannot load {path}")
    module = importlib.util.module_from_spec(spec)
    # Registered before exec so protobuf's descriptor pool sees one module, whoever imports it.
    sys.modules[_MODULE_NAME] = module
    spec.loader.exec_module(module)
    return module


def _cache_root() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "sph_client"


def _generate(schema: Path) -> Path:
    digest = hashlib.sha256(schema.read_bytes()).hexdigest()[:16]
    target = _cache_root() / digest
    if (target / f"{_MODULE_NAME}.py").is_file():
        return target
    protoc = os.environ.get("SPH_PROTOC") or shutil.which("protoc")
    if not protoc:
        raise ImportError("sph_client: protoc not found (apt-get install protobuf-compiler) and SPH_PB2_DIR unset")
    target.parent.mkdir(parents=True, exist_ok=True)
    # Generate into a private folder, then rename: concurrent first imports never see half a file.
    scratch = Path(tempfile.mkdtemp(prefix="gen-", dir=target.parent))
    try:
        subprocess.run(
            [protoc, f"--python_out={scratch}", f"-I{schema.parent}", str(schema)],
            check=True,
            capture_output=True,
        )
        try:
            os.rename(scratch, target)
        except OSError:
            if not (target / f"{_MODULE_NAME}.py").is_file():
                raise
    except subprocess.CalledProcessError as error:
        raise ImportError(f"sph_client: protoc failed: {error.stderr.decode(errors='replace')}") from error
    finally:
        if scratch.exists():
            shutil.rmtree(scratch, ignore_errors=True)
    return target


def load() -> ModuleType:
    if _MODULE_NAME in sys.modules:
        return sys.modules[_MODULE_NAME]
    prebuilt = os.environ.get("SPH_PB2_DIR")
    if prebuilt and (Path(prebuilt) / f"{_MODULE_NAME}.py").is_file():
        return _load_from(Path(prebuilt))
    return _load_from(_generate(schema_path()))


pb = load()
