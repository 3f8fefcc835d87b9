"""The data layer: manifest, resolution order, sha256 checks, errors that say what to do, fetch."""

from __future__ import annotations

import hashlib
import json

import pytest

from thesis_lib.lab import cli, data
from thesis_lib.lab.data import DataError


def test_every_manifest_entry_verifies():
    rows = data.verify()
    assert {name for name, _, _ in rows} == {"1eca", "1grm", "3rn3", "5mbn"}
    assert all(status == "ok" for _, status, _ in rows), rows


def test_manifest_sizes_match_the_files():
    for name, entry in data.manifest().items():
        assert data.path(name).stat().st_size == entry.size


def test_cli_data_verify(capsys):
    assert cli.main(["data", "verify"]) == 0
    assert capsys.readouterr().out.count("ok ") == 4


@pytest.fixture
def tiny(tmp_path, monkeypatch):
    """A compendium root with a one-entry manifest and a shared folder beside it."""
    root, shared = tmp_path / "repo", tmp_path / "shared"
    (root / "data").mkdir(parents=True)
    (shared / "data" / "x").mkdir(parents=True)
    payload = b"ATOM      1  N   GLY A   1\n"
    source = tmp_path / "source.txt"
    source.write_bytes(payload)
    digest = hashlib.sha256(payload).hexdigest()
    (root / "data" / "manifest.toml").write_text(
        f'[[file]]\nname = "toy"\nfile = "x/toy.pdb"\nsha256 = "{digest}"\nsize = {len(payload)}\n'
        f'url = "{source.as_uri()}"\norigin = "test"\nlicence = "CC0"\n'
    )
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(root))
    monkeypatch.setenv("THESIS_LAB_SHARED", str(shared))
    return root, shared, payload


def test_missing_file_names_it_and_what_to_do(tiny):
    with pytest.raises(DataError, match=r"'toy' \(x/toy.pdb\) is missing.*thesis-lab data fetch toy"):
        data.path("toy")


def test_wrong_hash_names_the_file_and_what_to_do(tiny):
    root, shared, payload = tiny
    (shared / "data" / "x" / "toy.pdb").write_bytes(payload + b"corrupt")
    with pytest.raises(DataError,
                       match=r"toy.pdb does not match its sha256.*delete it and run `thesis-lab data fetch toy`"):
        data.path("toy")
    assert cli.main(["data", "verify"]) == 1


def test_local_cache_comes_before_shared(tiny):
    root, shared, payload = tiny
    (shared / "data" / "x" / "toy.pdb").write_bytes(payload)
    assert data.path("toy") == shared / "data" / "x" / "toy.pdb"
    (root / "data" / "x").mkdir()
    (root / "data" / "x" / "toy.pdb").write_bytes(payload)
    assert data.path("toy") == root / "data" / "x" / "toy.pdb"


def test_unknown_name_lists_the_known_ones(tiny):
    with pytest.raises(DataError, match="unknown data set 'nope'; the manifest lists: toy"):
        data.path("nope")


def test_fetch_downloads_checks_and_caches(tiny):
    root, _, payload = tiny
    target = data.fetch("toy")
    assert target == root / "data" / "x" / "toy.pdb" and target.read_bytes() == payload
    assert data.path("toy") == target


def test_fetch_refuses_a_download_with_the_wrong_hash(tiny, tmp_path):
    root, _, _ = tiny
    (tmp_path / "source.txt").write_bytes(b"something else")
    with pytest.raises(DataError, match="does not match its sha256"):
        data.fetch("toy")
    assert not (root / "data" / "x" / "toy.pdb").exists()
    assert not list((root / "data" / "x").iterdir())


def _manifest(root, file="x/toy.pdb", **kw):
    payload = b"ATOM      1  N   GLY A   1\n"
    entry = {"name": "toy", "file": file, "sha256": hashlib.sha256(payload).hexdigest(), "size": len(payload),
             "url": "file:///nonexistent", "origin": "test", "licence": "CC0"}
    entry.update(kw)
    body = "\n".join(f"{k} = {json.dumps(v)}" for k, v in entry.items())
    (root / "data" / "manifest.toml").write_text(f"[[file]]\n{body}\n")


@pytest.mark.parametrize("file", ["../../x", "../outside.pdb", "/etc/passwd", "x/../../y", "./x", "x//y", "",
                                  "x\\..\\y", "a/./b", ".."])
def test_manifest_entries_outside_data_are_refused(tiny, file):
    """A manifest `file` leading outside data/ (../../x, /etc/passwd, ...) is refused by `path` and `data fetch`."""
    root, shared, payload = tiny
    _manifest(root, file=file)
    with pytest.raises(DataError, match="must be a relative path below data/"):
        data.path("toy")
    with pytest.raises(DataError, match="must be a relative path below data/"):
        data.fetch("toy")
    assert cli.main(["data", "fetch", "toy"]) == 2


def test_symlinks_out_of_data_are_refused(tiny, tmp_path):
    root, shared, payload = tiny
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "toy.pdb").write_bytes(payload)
    (root / "data" / "x").symlink_to(outside)
    with pytest.raises(DataError, match=r"leads outside .* \(through a symlink\)"):
        data.path("toy")
    with pytest.raises(DataError, match="leads outside"):
        data.fetch("toy")
    assert [p.name for p in outside.iterdir()] == ["toy.pdb"]


@pytest.mark.parametrize(
    "text, message",
    [
        ("[[file]\nname = 'x'", "is not valid TOML"),
        ("file = 3", "'file' must be an array of tables"),
        ("[[file]]\nname = 'x'", "missing"),
        (None, "sha256 must be 64 lowercase hex digits"),
        (None, "size must be a non-negative integer"),
        (None, "url must start with"),
        (None, "entry name"),
        (None, "listed twice"),
    ],
)
def test_malformed_manifests_give_clear_errors(tiny, text, message):
    """A malformed manifest gives a DataError naming the problem, not a raw TOMLDecodeError."""
    root, _, _ = tiny
    if text is not None:
        (root / "data" / "manifest.toml").write_text(text)
    elif "sha256" in message:
        _manifest(root, sha256="ABC")
    elif "size" in message:
        _manifest(root, size=-1)
    elif "url" in message:
        _manifest(root, url="ftp://x")
    elif "entry name" in message:
        _manifest(root, name="../x")
    else:
        _manifest(root)
        text = (root / "data" / "manifest.toml").read_text()
        (root / "data" / "manifest.toml").write_text(text + "\n" + text)
    with pytest.raises(DataError, match=message):
        data.manifest()
    assert cli.main(["data", "verify"]) == 2


def test_an_interrupted_fetch_leaves_data_as_it_was(tiny, monkeypatch):
    root, _, payload = tiny
    (root / "data" / "x").mkdir()
    (root / "data" / "x" / "toy.pdb").write_bytes(b"old bytes")

    def broken(response, fh):
        fh.write(payload[:5])
        raise KeyboardInterrupt

    monkeypatch.setattr(data.shutil, "copyfileobj", broken)
    with pytest.raises(KeyboardInterrupt):
        data.fetch("toy")
    assert [p.name for p in (root / "data" / "x").iterdir()] == ["toy.pdb"]
    assert (root / "data" / "x" / "toy.pdb").read_bytes() == b"old bytes"
