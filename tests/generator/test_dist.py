"""`make dist`: every release artifact, named with the spec's version, carries the licence, and
installs where its ecosystem installs it: the wheel into a fresh venv, the C archive with CMake and
pkg-config into a prefix a consumer project builds against. (The crate is built from its packaged
files alone by `cargo package` itself, during `make dist`.)"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest

import ilahrs
from generator import ROOT

LICENCE = "MIT OR Apache-2.0"
VERSION = ilahrs.__version__
FINGERPRINT = f"{ilahrs.WIRE_FINGERPRINT:016x}"
EXPECTED = {
    f"ilahrs-{VERSION}-py3-none-any.whl",
    f"ilahrs-{VERSION}.tar.gz",
    f"ilahrs-{VERSION}.crate",
    f"ilahrs-c-{VERSION}.tar.gz",
    f"ilahrs-{VERSION}.ksy",
    f"ilahrs-wireshark-{VERSION}.lua",
    "SHA256SUMS",
}


def _run(*args: str | Path, cwd: Path | None = None, env: dict[str, str] | None = None) -> str:
    result = subprocess.run(
        [str(a) for a in args], capture_output=True, text=True, cwd=cwd, env=env, timeout=600, check=False
    )
    assert result.returncode == 0, f"{args}: {result.stdout[-3000:]}\n{result.stderr[-3000:]}"
    return result.stdout


@pytest.fixture(scope="module")
def dist(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("release") / "dist"
    _run("make", "--no-print-directory", "dist", f"DIST={out}", cwd=ROOT)
    return out


def test_dist_holds_each_artifact_named_with_the_version(dist: Path) -> None:
    assert {p.name for p in dist.iterdir()} == EXPECTED
    sums = (dist / "SHA256SUMS").read_text(encoding="utf-8").splitlines()
    listed = {}
    for line in sums:
        digest, name = line.split(maxsplit=1)
        listed[name] = digest
    assert set(listed) == EXPECTED - {"SHA256SUMS"}
    for name, digest in listed.items():
        assert hashlib.sha256((dist / name).read_bytes()).hexdigest() == digest, name


def test_the_changelog_has_an_entry_for_the_spec_version() -> None:
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert "https://keepachangelog.com" in text
    assert re.search(rf"^## \[{re.escape(VERSION)}\] - ", text, re.MULTILINE)


def test_every_artifact_carries_the_licence(dist: Path) -> None:
    root_licence = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert f"SPDX-License-Identifier: {LICENCE}" in root_licence
    texts = {name: (ROOT / name).read_text(encoding="utf-8") for name in ("LICENSE-MIT", "LICENSE-APACHE")}

    with zipfile.ZipFile(dist / f"ilahrs-{VERSION}-py3-none-any.whl") as wheel:
        names = wheel.namelist()
        metadata = wheel.read(f"ilahrs-{VERSION}.dist-info/METADATA").decode()
        assert f"License: {LICENCE}" in metadata
        for name, text in texts.items():
            found = [n for n in names if n.endswith(f"/{name}")]
            assert found and wheel.read(found[0]).decode() == text, name
    for archive, prefix in (
        (f"ilahrs-{VERSION}.tar.gz", f"ilahrs-{VERSION}"),
        (f"ilahrs-{VERSION}.crate", f"ilahrs-{VERSION}"),
        (f"ilahrs-c-{VERSION}.tar.gz", f"ilahrs-c-{VERSION}"),
    ):
        with tarfile.open(dist / archive) as tar:
            for name, text in texts.items():
                member = tar.extractfile(f"{prefix}/{name}")
                assert member is not None and member.read().decode() == text, (archive, name)
            if archive.endswith(".crate"):
                manifest = tar.extractfile(f"{prefix}/Cargo.toml")
                assert manifest is not None and f'license = "{LICENCE}"' in manifest.read().decode()
            if archive.startswith("ilahrs-c-"):
                header = tar.extractfile(f"{prefix}/ilahrs.h")
                assert header is not None and f"SPDX-License-Identifier: {LICENCE}" in header.read().decode()
    ksy = (dist / f"ilahrs-{VERSION}.ksy").read_text(encoding="utf-8")
    assert re.search(rf"^meta:\n(  .*\n)*  license: {re.escape(LICENCE)}$", ksy, re.MULTILINE)
    lua = (dist / f"ilahrs-wireshark-{VERSION}.lua").read_text(encoding="utf-8")
    assert f"-- SPDX-License-Identifier: {LICENCE}" in lua.splitlines()[:5]


def test_the_wheel_installs_into_a_fresh_venv(dist: Path, tmp_path: Path) -> None:
    _run(
        sys.executable,
        "-m",
        "twine",
        "check",
        "--strict",
        dist / f"ilahrs-{VERSION}-py3-none-any.whl",
        dist / f"ilahrs-{VERSION}.tar.gz",
    )
    venv = tmp_path / "venv"
    _run(sys.executable, "-m", "venv", venv)
    python = venv / "bin" / "python"
    _run(
        python,
        "-m",
        "pip",
        "install",
        "--quiet",
        "--no-index",
        "--no-deps",
        dist / f"ilahrs-{VERSION}-py3-none-any.whl",
    )
    # Run from elsewhere, so that nothing of the checkout is imported.
    out = _run(python, "-c", "import ilahrs; print(ilahrs.__file__, ilahrs.__version__)", cwd=tmp_path)
    assert out.startswith(str(venv)) and out.split()[1] == VERSION
    assert FINGERPRINT in _run(venv / "bin" / "ilahrs", "--version", cwd=tmp_path)


def test_the_sdist_holds_the_package_and_its_metadata(dist: Path) -> None:
    with tarfile.open(dist / f"ilahrs-{VERSION}.tar.gz") as tar:
        names = set(tar.getnames())
    for part in ("pyproject.toml", "README.md", "PKG-INFO", "ilahrs/__init__.py", "ilahrs/py.typed"):
        assert f"ilahrs-{VERSION}/{part}" in names, part


CONSUMER_CMAKE = """cmake_minimum_required(VERSION 3.13)
project(consumer LANGUAGES C)
find_package(ilahrs {major}.0 REQUIRED)
add_executable(consumer main.c)
target_link_libraries(consumer PRIVATE ilahrs::ilahrs)
"""

CONSUMER_MAIN = r"""#include <inttypes.h>
#include <stdio.h>
#include <ilahrs.h>

int main(void)
{
    /* The frame checksum of the header bytes: a call into the installed library. */
    static const uint8_t data[] = {0xAAu, 0x55u};
    printf("%s %016" PRIx64 " %04x\n", ILAHRS_SPEC_VERSION, (uint64_t)ILAHRS_WIRE_FINGERPRINT,
           (unsigned)ilahrs_checksum(data, sizeof data));
    return 0;
}
"""


def test_the_c_archive_installs_and_a_consumer_builds_against_it(dist: Path, tmp_path: Path) -> None:
    if shutil.which("cmake") is None or shutil.which("cc") is None:
        pytest.skip("cmake and a C compiler are needed")
    with tarfile.open(dist / f"ilahrs-c-{VERSION}.tar.gz") as tar:
        tar.extractall(tmp_path / "src", filter="data")
    source = tmp_path / "src" / f"ilahrs-c-{VERSION}"
    prefix = tmp_path / "prefix"
    _run(
        "cmake",
        "-S",
        source,
        "-B",
        tmp_path / "build",
        f"-DCMAKE_INSTALL_PREFIX={prefix}",
        "-DCMAKE_BUILD_TYPE=Release",
    )
    _run("cmake", "--build", tmp_path / "build")
    _run("cmake", "--install", tmp_path / "build")
    assert (prefix / "share" / "doc" / "ilahrs" / "LICENSE-MIT").is_file()

    consumer = tmp_path / "consumer"
    consumer.mkdir()
    (consumer / "CMakeLists.txt").write_text(CONSUMER_CMAKE.format(major=VERSION.split(".")[0]), encoding="utf-8")
    (consumer / "main.c").write_text(CONSUMER_MAIN, encoding="utf-8")
    _run("cmake", "-S", consumer, "-B", consumer / "build", f"-DCMAKE_PREFIX_PATH={prefix}")
    _run("cmake", "--build", consumer / "build")
    checksum = ilahrs.checksum(bytes((0xAA, 0x55)))
    expected = f"{VERSION} {FINGERPRINT} {checksum:04x}"
    assert _run(consumer / "build" / "consumer").strip() == expected

    # The same program with pkg-config and the compiler alone.
    if shutil.which("pkg-config") is not None:
        pc_dirs = [str(p.parent) for p in prefix.rglob("ilahrs.pc")]
        env = {**os.environ, "PKG_CONFIG_PATH": os.pathsep.join(pc_dirs)}
        flags = _run("pkg-config", "--cflags", "--libs", "ilahrs", env=env).split()
        assert _run("pkg-config", "--modversion", "ilahrs", env=env).strip() == VERSION
        _run("cc", "-std=c99", "-o", consumer / "pc_consumer", consumer / "main.c", *flags)
        assert _run(consumer / "pc_consumer").strip() == expected
