"""The build backend of sph_client (PEP 517): a pure-Python wheel made with the standard library
alone, so that `pip install ./clients/python` needs no package index. pip builds in an isolated
environment and would otherwise fetch a backend (setuptools) from an index before it could start.

It reads pyproject.toml ([project] and [tool.sph_client]) and writes what PEP 427 and the core
metadata specification ask of a wheel: the packages' files, METADATA, WHEEL, entry_points.txt and
RECORD. Python 3.11 or newer (tomllib)."""

import base64
import csv
import hashlib
import io
import os
import tarfile
import tomllib
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def _project():
    with open(os.path.join(ROOT, "pyproject.toml"), "rb") as f:
        data = tomllib.load(f)
    return data["project"], data.get("tool", {}).get("sph_client", {})


def _dist_name(project):
    return project["name"].replace("-", "_")


def _metadata(project):
    lines = ["Metadata-Version: 2.1", f"Name: {project['name']}", f"Version: {project['version']}",
             f"Summary: {project['description']}", f"Requires-Python: {project['requires-python']}"]
    lines += [f"Requires-Dist: {dependency}" for dependency in project.get("dependencies", [])]
    readme = project.get("readme")
    body = ""
    if readme:
        lines.append("Description-Content-Type: text/markdown")
        with open(os.path.join(ROOT, readme), encoding="utf-8") as f:
            body = "\n" + f.read()
    return "\n".join(lines) + "\n" + body


def _package_files(tool):
    """(path in the wheel, path on disk) of every file of the packages, links followed."""
    for package in tool["packages"]:
        folder = os.path.join(ROOT, *package.split("."))
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            if os.path.isfile(path) and (name.endswith(".py") or name in tool.get("package-data", [])):
                yield "/".join(package.split(".") + [name]), os.path.realpath(path)


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return [name, f"sha256={digest}", str(len(data))]


# The hooks pip calls.

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    project, tool = _project()
    dist = f"{_dist_name(project)}-{project['version']}"
    wheel_name = f"{dist}-py3-none-any.whl"
    info = f"{dist}.dist-info"
    records = []
    with zipfile.ZipFile(os.path.join(wheel_directory, wheel_name), "w", zipfile.ZIP_DEFLATED) as wheel:
        def add(name, data):
            wheel.writestr(name, data)
            records.append(_record_line(name, data))

        for name, path in _package_files(tool):
            with open(path, "rb") as f:
                add(name, f.read())
        add(f"{info}/METADATA", _metadata(project).encode())
        add(f"{info}/WHEEL", b"Wheel-Version: 1.0\nGenerator: sph_client_build\nRoot-Is-Purelib: true\n"
                             b"Tag: py3-none-any\n")
        scripts = project.get("scripts", {})
        if scripts:
            entries = "[console_scripts]\n" + "".join(f"{k} = {v}\n" for k, v in scripts.items())
            add(f"{info}/entry_points.txt", entries.encode())
        record = io.StringIO()
        writer = csv.writer(record, lineterminator="\n")
        writer.writerows(records + [[f"{info}/RECORD", "", ""]])
        wheel.writestr(f"{info}/RECORD", record.getvalue())
    return wheel_name


def build_sdist(sdist_directory, config_settings=None):
    project, tool = _project()
    dist = f"{_dist_name(project)}-{project['version']}"
    with tarfile.open(os.path.join(sdist_directory, f"{dist}.tar.gz"), "w:gz") as sdist:
        for name in ["pyproject.toml", project.get("readme", "README.md"), "build_backend/sph_client_build.py"]:
            sdist.add(os.path.join(ROOT, name), f"{dist}/{name}")
        for name, path in _package_files(tool):
            sdist.add(path, f"{dist}/{name}")
        info = tarfile.TarInfo(f"{dist}/PKG-INFO")
        data = _metadata(project).encode()
        info.size = len(data)
        sdist.addfile(info, io.BytesIO(data))
    return f"{dist}.tar.gz"
