"""What `run -o` and `study --results` may replace: only an earlier result of this program.

Everything else is refused in one line, exit status 2, before any computing and with nothing
written. The device case is played by stand-ins inside tmp_path (a named pipe, a symbolic
link); /dev/null itself is only looked at, with every way of writing made to fail first.
"""
import errno
import os
import re
import stat
import textwrap

import netCDF4
import pytest

import bearing_sweep
from bearing_sweep import cli, stores
from bearing_sweep.stores import paths


def test_the_definition_itself_is_refused(tmp_path, no_computing, four_points, refused):
    definition = tmp_path / "def.toml"
    definition.write_text(four_points)
    err = refused(definition, definition)
    assert "is the sweep definition itself" in err
    assert definition.read_text() == four_points


def test_a_folder_is_refused_before_computing(tmp_path, no_computing, refused):
    (tmp_path / "results").mkdir()
    assert "is a folder" in refused(tmp_path / "results")


def test_a_named_pipe_is_refused_without_being_opened(tmp_path, four_points, run_cli):
    # A stand-in for a device such as /dev/null: not a regular file. Opening a pipe for reading
    # would block, so a run that opened it would reach the timeout here.
    (tmp_path / "def.toml").write_text(four_points)
    os.mkfifo(tmp_path / "pipe")
    done = run_cli("run", "def.toml", "-o", "pipe", "--workers", "0", cwd=tmp_path, timeout=120)
    assert done.returncode == 2, done.stderr
    assert done.stderr.strip() == ("error: pipe: exists and is a named pipe, not an earlier "
                                   "result; refusing to replace it (choose another output)")
    assert stat.S_ISFIFO((tmp_path / "pipe").lstat().st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["def.toml", "pipe"]


def test_a_symbolic_link_is_refused_and_its_target_kept(tmp_path, no_computing, refused):
    target = tmp_path / "target.nc"
    target.write_bytes(b"someone else's data")
    (tmp_path / "link.nc").symlink_to(target)
    assert "is a symbolic link" in refused(tmp_path / "link.nc")
    assert target.read_bytes() == b"someone else's data"


def test_another_programs_file_is_refused(tmp_path, no_computing, refused):
    (tmp_path / "notes.nc").write_text("not a netCDF file")
    assert "not a netCDF file" in refused(tmp_path / "notes.nc")
    with netCDF4.Dataset(tmp_path / "theirs.nc", "w") as theirs:
        theirs.source = "another model 2.0"
    assert "do not name bearing-sweep" in refused(tmp_path / "theirs.nc")
    (tmp_path / "empty.nc").touch()
    refused(tmp_path / "empty.nc")


def test_a_file_as_the_outputs_folder_is_refused(tmp_path, no_computing, refused):
    (tmp_path / "plain").write_text("a file")
    err = refused(tmp_path / "plain" / "deeper" / "out.nc")
    assert "its folder cannot be created" in err and "is not a folder" in err


def test_an_earlier_result_is_replaced(tmp_path, capsys, four_points):
    (tmp_path / "def.toml").write_text(four_points)
    output = tmp_path / "out.nc"
    arguments = ["run", str(tmp_path / "def.toml"), "-o", str(output), "--workers", "0"]
    assert cli.main(arguments) == 0
    (tmp_path / "def.toml").write_text(four_points.replace('"4 kN"', '"5 kN"'))
    assert cli.main(arguments) == 0, capsys.readouterr().err
    assert stores.open_result(output).radial_load.values.tolist() == [2000, 5000]


def test_dev_null_is_refused_by_looking_only(monkeypatch):
    device = "/dev/null"
    before = os.stat(device)

    def written(*args, **kwargs):
        raise AssertionError("an attempt to write near /dev/null")

    # Every way the check could write, made to fail before it could: it may only look.
    for name in ("open", "replace", "rename", "unlink", "mkdir", "makedirs", "mkfifo", "remove"):
        monkeypatch.setattr(os, name, written)
    monkeypatch.setattr(netCDF4, "Dataset", written)
    monkeypatch.setattr("builtins.open", written)
    with pytest.raises(paths.UnsafeOutput, match="is a device"):
        paths.check_output(device)
    after = os.stat(device)
    assert (after.st_ino, after.st_mode, after.st_rdev) == \
        (before.st_ino, before.st_mode, before.st_rdev)


def test_study_refuses_a_result_path_that_is_not_a_result(tmp_path, four_points, run_cli):
    study = tmp_path / "studies" / "tiny"
    study.mkdir(parents=True)
    (study / "loads.toml").write_text(four_points)
    (study / "figures.py").write_text(textwrap.dedent("""
        FIGURES = {}
        def draw(results, figures):
            pass
        """))
    (tmp_path / "results" / "tiny").mkdir(parents=True)
    (tmp_path / "results" / "tiny" / "loads.nc").write_text("my own notes")
    done = run_cli("study", "tiny", "--studies", "studies", cwd=tmp_path, timeout=120)
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "results/tiny/loads.nc: exists and is not a netCDF file" in done.stderr
    assert (tmp_path / "results" / "tiny" / "loads.nc").read_text() == "my own notes"
    assert not (tmp_path / "figures").exists()


#: Output names that do not say plainly what they are, and what the refusal says.
ODD_NAMES = {".zarr": "is only a suffix; name the store, as result.zarr",
             ".ZARR": "is only a suffix; name the store, as result.ZARR",
             ".nc": "is only a suffix; name the file, as result.nc",
             "deeper/.zarr/": "is only a suffix; name the store",
             "x.zarr.": "ends in a dot, which some filesystems drop; name it x.zarr",
             "x.nc..": "ends in a dot, which some filesystems drop; name it x.nc",
             "x.": "ends in a dot",
             "x.nc/": "names a folder (it ends in /), and a netCDF result is a file: name it x.nc",
             "results/": "names a folder"}


@pytest.mark.parametrize("name", ODD_NAMES)
def test_an_odd_output_name_is_refused(tmp_path, no_computing, name, four_points, refused):
    err = refused(f"{tmp_path}/{name}")
    assert f"{tmp_path}/{name}: {ODD_NAMES[name]}" in err
    with pytest.raises(paths.UnsafeOutput, match=re.escape(ODD_NAMES[name])):
        bearing_sweep.run(four_points, output=f"{tmp_path}/{name}", workers=0, progress=False)


def test_a_store_is_named_by_its_suffix_in_any_case_with_or_without_a_slash(tmp_path, capsys,
                                                                            four_points):
    (tmp_path / "def.toml").write_text(four_points)
    for name in ("upper.ZARR", "slashed.zarr/"):
        assert cli.main(["run", str(tmp_path / "def.toml"), "-o", f"{tmp_path}/{name}",
                         "--workers", "0", "--quiet"]) == 0
    capsys.readouterr()
    for name in ("upper.ZARR", "slashed.zarr"):
        assert (tmp_path / name / ".zgroup").is_file()
        assert stores.open_result(tmp_path / name).status.shape == (2, 2)


def test_a_file_where_a_store_goes_is_refused(tmp_path, no_computing, refused):
    # our own netCDF file under a store's name: a store is a folder, never written over a file
    with netCDF4.Dataset(tmp_path / "ours.zarr", "w") as ours:
        ours.source = "bearing-sweep 0.1.0"
    err = refused(tmp_path / "ours.zarr")
    assert "ours.zarr: exists and is a file; a .zarr output is a zarr store, a folder" in err


#: A lock file that cannot be made, by the error the system gives, and the exit status.
LOCK_FAILURES = {"a filesystem that takes no files, as /proc": (errno.ENOENT, 2),
                 "a read-only folder": (errno.EROFS, 2),
                 "no permission": (errno.EACCES, 2),
                 "a full disk": (errno.ENOSPC, 1)}


@pytest.mark.parametrize("case", LOCK_FAILURES)
def test_a_lock_file_that_cannot_be_made_says_so(tmp_path, capsys, monkeypatch, case, four_points,
                                                 tree):
    # Before, every one of them said that another run was writing the output.
    code, status = LOCK_FAILURES[case]
    opened = os.open

    def refused_there(path, flags, *args, **kwargs):  # no new file in tmp_path
        if flags & os.O_CREAT and os.path.dirname(path) == str(tmp_path):
            raise OSError(code, os.strerror(code), os.fspath(path))
        return opened(path, flags, *args, **kwargs)

    (tmp_path / "def.toml").write_text(four_points)
    before = tree(tmp_path)
    monkeypatch.setattr(os, "open", refused_there)
    assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / "out.nc"),
                     "--workers", "0", "--quiet"]) == status
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "another bearing-sweep run" not in err, err
    assert f"its lock file .out.nc.lock cannot be made in {tmp_path}" in err
    assert os.strerror(code) in err
    assert tree(tmp_path) == before


def test_a_folder_where_the_lock_goes_says_so(tmp_path, refused):
    (tmp_path / ".out.nc.lock").mkdir()
    err = refused(tmp_path / "out.nc")
    assert f"its lock file .out.nc.lock cannot be made in {tmp_path} (Is a directory)" in err


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="no /proc")
def test_an_output_in_proc_is_refused_for_what_it_is(tmp_path, capsys, four_points):
    # The reproduction: nothing can be made in /proc (the attempt makes nothing).
    (tmp_path / "def.toml").write_text(four_points)
    assert cli.main(["run", str(tmp_path / "def.toml"), "-o", "/proc/x.nc", "--workers", "0",
                     "--quiet"]) == 2
    assert capsys.readouterr().err == (
        "error: /proc/x.nc: cannot be written: its lock file .x.nc.lock cannot be made in /proc "
        "(No such file or directory); choose another output\n")
    # The schema and a figure alike, naming the path asked for, not a temporary one.
    assert cli.main(["schema", "-o", "/proc/x.json"]) == 2
    assert capsys.readouterr().err.startswith("error: /proc/x.json: cannot be written: its lock")
    result = tmp_path / "r.nc"
    assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(result), "--workers", "0",
                     "--quiet"]) == 0
    capsys.readouterr()
    assert cli.main(["plot", str(result), "-o", "/proc/x.png"]) == 2
    assert capsys.readouterr().err.startswith("error: /proc/x.png: cannot be written: its lock")


#: Paths inside a zarr store or a parts folder, made before the run (None: not made).
INSIDE = {"a netCDF file in a store": ("s.zarr", "s.zarr/y.nc"),
          "a store in a store": ("s.zarr", "s.zarr/inner.zarr"),
          "in a store's subfolder": ("s.zarr", "s.zarr/status/y.nc"),
          "in a store yet to be": (None, "new.ZARR/y.nc"),
          "in a store through a link": ("s.zarr", "link/y.nc"),
          "in another output's parts": ("r.nc.parts", "r.nc.parts/x.nc"),
          "in a parts folder yet to be": (None, "results/r.nc.parts/x.nc"),
          "in a store's parts": ("s.zarr", "s.zarr.parts/store.zarr/y.nc")}


@pytest.mark.parametrize("case", INSIDE)
def test_an_output_inside_a_store_or_a_parts_folder_is_refused(tmp_path, capsys, case, four_points,
                                                               refused):
    made, output = INSIDE[case]
    (tmp_path / "def.toml").write_text(four_points)
    if made == "s.zarr":
        assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / made),
                         "--workers", "0", "--quiet"]) == 0
        (tmp_path / "link").symlink_to(tmp_path / made)
    elif made:
        (tmp_path / made).mkdir()
    capsys.readouterr()
    err = refused(tmp_path / output)
    assert "is inside" in err and "choose a path outside it" in err
    inside = "a .zarr folder is a zarr store" if ".zarr/" in output.lower() or "link" in case \
        else "the folder where a run keeps the finished chunks of"
    assert inside in err


def test_an_analysis_or_a_figure_inside_a_store_is_refused(tmp_path, capsys, four_points, tree):
    (tmp_path / "def.toml").write_text(four_points)
    assert cli.main(["run", str(tmp_path / "def.toml"), "-o", str(tmp_path / "s.zarr"),
                     "--workers", "0", "--quiet"]) == 0
    capsys.readouterr()
    before = tree(tmp_path)
    for command in (["analyze", str(tmp_path / "s.zarr"), "-o", str(tmp_path / "s.zarr/a.nc")],
                    ["plot", str(tmp_path / "s.zarr"), "-o", str(tmp_path / "s.zarr/f.png")],
                    ["schema", "-o", str(tmp_path / "s.zarr/schema.json")]):
        assert cli.main(command) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "a .zarr folder is a zarr store" in err, err
    with pytest.raises(paths.UnsafeOutput, match="is inside"):
        bearing_sweep.analyze(tmp_path / "s.zarr", output=tmp_path / "s.zarr" / "a.zarr")
    assert tree(tmp_path) == before
