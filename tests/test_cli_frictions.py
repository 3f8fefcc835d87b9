"""What a new user of ``thesis-lab`` met: data verify of a name that matches nothing, a sweep table too
wide for the terminal, help without the experiments, an unknown option answered with the top-level
help, no "did you mean", ranges checked only inside a kernel, floats printed with every digit, RST
markup in the help."""

from __future__ import annotations

import csv
import hashlib
import re
from pathlib import Path

import pytest
from lab_helpers import (
    TOY_RESULTS,
    cli,
    make_project,
    root,  # noqa: F401 (the project fixture)
    set_default,
)

from thesis_lib.lab import cli as lab_cli
from thesis_lib.lab import runner as lab_runner
from thesis_lib.lab import sweep as lab_sweep
from thesis_lib.lab.data import DataError, verify
from thesis_lib.lab.experiments import (
    ParameterError,
    did_you_mean,
    experiment_parameters,
    list_experiments,
    parameter_ranges,
    resolve_parameters,
    run_hash,
)

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture
def no_kernels(monkeypatch):
    """Any attempt to execute a notebook fails the test (a check must come before any kernel starts)."""
    started = []

    def refuse(*args, **kwargs):
        started.append(args)
        raise AssertionError("a kernel was asked to start")

    monkeypatch.setattr(lab_runner, "cancellable", refuse)
    monkeypatch.setattr(lab_runner, "execute", refuse)
    monkeypatch.setattr(lab_sweep, "execute", refuse)
    return started


# 1. data verify checks only what its arguments select; an argument that selects nothing is an error


def _second_data_set(root: Path) -> str:
    payload = b"HETATM    1  O   HOH A   1\n"
    (root / "data" / "x" / "water.pdb").write_bytes(payload)
    digest = hashlib.sha256(payload).hexdigest()
    with open(root / "data" / "manifest.toml", "a") as fh:
        fh.write(f'\n[[file]]\nname = "water"\nfile = "x/water.pdb"\nsha256 = "{digest}"\nsize = {len(payload)}\n'
                 'url = "file:///nonexistent"\norigin = "test"\nlicence = "CC0"\n')
    return digest


def test_data_verify_checks_only_the_data_sets_its_arguments_select(root, capsys):
    digest = _second_data_set(root)
    assert [name for name, _, _ in verify()] == ["toy-data", "water"]
    assert [name for name, _, _ in verify(names=["water"])] == ["water"]
    assert [name for name, _, _ in verify(names=["toy"])] == ["toy-data"]  # the start of a name
    assert [name for name, _, _ in verify(names=[digest[:6].upper()])] == ["water"]  # a sha256 prefix
    assert [name for name, _, _ in verify(names=["water", "toy-data", "wat"])] == ["toy-data", "water"]
    assert lab_cli.main(["data", "verify", "wat"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("ok    water: ") and "toy-data" not in out and len(out.splitlines()) == 1


def test_data_verify_of_an_argument_that_selects_nothing_is_an_error(root, capsys):
    _second_data_set(root)
    for bad in ("1ecaa", "toy-data-2", "ab"):  # "ab": too few hex digits for a sha256 prefix
        with pytest.raises(DataError, match=f"no data set matches {bad!r}.*the manifest lists: toy-data, water"):
            verify(names=["water", bad])
    assert lab_cli.main(["data", "verify", "watr"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""  # nothing was checked
    assert captured.err == ("error: no data set matches 'watr' (give a name, the start of one, or at least 4 hex "
                            "digits of a sha256); the manifest lists: toy-data, water; did you mean 'water'?\n")


def test_data_verify_of_the_project_names_its_data_sets():
    with pytest.raises(DataError, match=r"'1ecaa' .* lists: 1eca, 1grm, 3rn3, 5mbn; did you mean '1eca'\?$"):
        verify(ROOT / "data" / "manifest.toml", names=["1ecaa"])
    assert [name for name, _, _ in verify(ROOT / "data" / "manifest.toml", names=["1e", "5mbn"])] == ["1eca", "5mbn"]


# 2. a sweep prints a compact summary on the terminal and names the full table it wrote


def test_sweep_prints_a_compact_summary_and_the_path_of_the_full_table(root):
    label = "a-very-long-label-" * 10
    proc = cli(root, "sweep", "toy", "-q", "-p", "n", "1", "2", "-p", "label", label, "-p", "fail", "false", "true")
    assert proc.returncode == 1, proc.stderr  # the runs with fail=true failed
    lines = proc.stdout.splitlines()
    assert all(len(line) <= 100 for line in lines[:-1]), [len(line) for line in lines]  # the last: the path
    assert lines[0].startswith("`thesis-lab sweep toy -p n 1 2 -p label a-very")  # the command of the table
    assert lines[1] == "4 runs: 2 ok, 2 failed"
    assert lines[2].startswith("fixed: label=a-very-long-l…")  # one value: not a column; shortened
    header = lines[3].split()
    assert header[:3] == ["n", "fail", "status"] and "square" in header
    assert [line.split()[:3] for line in lines[4:8]] == [["1", "False", "ok"], ["1", "True", "failed"],
                                                          ["2", "False", "ok"], ["2", "True", "failed"]]
    squares = [line.split()[header.index("square")] for line in lines[4:8] if " ok " in line]
    assert squares == ["1", "4"]
    table = Path(re.fullmatch(r"full table: (\S+) \(and \S+\.md\)", lines[-1]).group(1))
    with open(table, newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 4 and rows[0]["label"] == label  # the full table keeps every column and value
    assert {"n", "label", "fail", "status", "run", "seconds", "worker", *TOY_RESULTS} <= set(rows[0])
    assert label in table.with_suffix(".md").read_text()


def test_the_summary_leaves_out_the_result_columns_that_do_not_fit():
    runs = [lab_runner.RunResult("e", {"n": n, "x": 0.1234567}, Path(f"/r/{n}"), "ok",
                                 results={f"result_number_{i:02d}": 1 / 3 for i in range(12)}) for n in (1, 2)]
    lines = lab_cli._summary(runs, ["n", "x"])
    assert lines[0] == "2 runs: 2 ok" and lines[1] == "fixed: x=0.1235"
    assert all(len(line) <= 100 for line in lines)
    assert lines[2].split()[:3] == ["n", "status", "result_number_00"]
    assert lines[3].split()[:3] == ["1", "ok", "0.3333"]
    shown = len(lines[2].split()) - 2
    assert 0 < shown < 12 and lines[-1].startswith(f"not shown ({12 - shown} result columns): result_number_")


# 3. run --help describes its arguments and lists the experiments; 8. no RST markup in any help


def test_run_help_describes_its_arguments_and_lists_the_experiments(tmp_path, capsys):
    project = make_project(tmp_path / "project", ("toy", "two-circles"))
    assert lab_cli.main(["--project", str(project), "run", "--help"]) == 0
    out = capsys.readouterr().out
    assert re.search(r"experiment +the experiment: a name that `thesis-lab list` shows", out)
    assert re.search(r"-p NAME VALUE, --param NAME VALUE\n +set a parameter", out)
    assert out.rstrip().endswith("experiments (thesis-lab list shows their parameters):\n  toy\n  two-circles")
    assert lab_cli.main(["--project", str(project), "sweep", "--help"]) == 0
    assert capsys.readouterr().out.rstrip().endswith("\n  toy\n  two-circles")


def test_help_texts_carry_no_rst_markup(root, capsys):
    parser = lab_cli.build_parser()
    commands = parser.commands.choices
    assert set(commands) == {"run", "sweep", "collect", "store", "list", "report", "data"}
    for text in [parser.format_help(), *(p.format_help() for p in commands.values())]:
        assert "``" not in text, text
    assert "The thesis-lab command line: run and sweep experiments" in parser.format_help()


# 4. an unknown option of a subcommand is answered with that subcommand's usage


@pytest.mark.parametrize("argv, usage", [
    (["run", "toy", "--bogus"], "expected: thesis-lab run [-h] [-p NAME VALUE] [--force] [-q] experiment ("),
    (["sweep", "toy", "-p", "n", "1", "--frobnicate"], "expected: thesis-lab sweep [-h] [-p NAME VALUE [NAME VALUE"),
    (["data", "verify", "--all"], "expected: thesis-lab data [-h] {verify,fetch} [names ...] ("),
])
def test_an_unknown_option_shows_the_subcommand_usage(root, capsys, no_kernels, argv, usage):
    assert lab_cli.main(argv) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"error: unrecognized arguments: {argv[-1]}; {usage}")
    assert err.endswith(f"(see `thesis-lab {argv[0]} --help`)\n") and err.count("\n") == 1  # one line
    assert "`thesis-lab --help`" not in err
    assert no_kernels == []


# 5. a misspelled experiment or parameter gets a "did you mean"


def test_a_misspelled_experiment_or_parameter_gets_did_you_mean(root, capsys, no_kernels):
    assert lab_cli.main(["run", "tyo"]) == 2
    assert capsys.readouterr().err == "error: unknown experiment 'tyo'; known experiments: toy; did you mean 'toy'?\n"
    assert lab_cli.main(["sweep", "toy", "-p", "sizez", "1"]) == 2
    assert capsys.readouterr().err.endswith("has no parameter 'sizez'; its parameters are: n, x, label, flag, sizes, "
                                            "fail, sleep, data_name, output_mb, work; did you mean 'sizes'?\n")
    assert lab_cli.main(["run", "nope"]) == 2  # nothing close: no suggestion
    assert capsys.readouterr().err == "error: unknown experiment 'nope'; known experiments: toy\n"
    assert did_you_mean("two-circle", ["two-circles", "two-circles-landmarks", "proteins"]) == \
        "; did you mean 'two-circles' or 'two-circles-landmarks'?"
    assert no_kernels == []


# 6. value ranges, declared in experiments/parameters.toml, are checked before any kernel starts


def _ranges(root: Path, text: str) -> None:
    (root / "experiments" / "parameters.toml").write_text(text)


def test_a_value_out_of_range_is_refused_before_any_kernel_starts(root, capsys, no_kernels):
    _ranges(root, "[toy]\nn = { min = 1 }\nx = { above = 0, max = 1 }\nsizes = { min = 1 }\n")
    cases = [
        (["run", "toy", "-p", "n", "0"], "parameter 'n' of toy is out of range: got 0; allowed: n >= 1"),
        (["run", "toy", "-p", "x", "0"], "parameter 'x' of toy is out of range: got 0.0; allowed: 0 < x <= 1"),
        (["run", "toy", "-p", "sizes", "5,0"], "got item 0 of [5, 0]; allowed: sizes >= 1"),
        (["sweep", "toy", "-p", "x", "0.5", "1.5"], "parameter 'x' of toy is out of range: got 1.5"),
        (["collect", "toy", "-p", "n", "-3", "3"], "parameter 'n' of toy is out of range: got -3"),
    ]
    for argv, message in cases:
        assert lab_cli.main(argv) == 2, argv
        err = capsys.readouterr().err
        assert err.startswith("error: ") and message in err, (argv, err)
        assert "parameters.toml" in err
    assert no_kernels == [] and not (root / "runs").exists()  # nothing ran, nothing was written
    assert resolve_parameters("toy", {"n": "1", "x": "1"})["x"] == 1.0  # the bounds themselves are allowed


def test_a_list_parameter_may_need_items(root, capsys, no_kernels):
    _ranges(root, "[toy]\nsizes = { min = 1, min_items = 2 }\n")
    assert lab_cli.main(["run", "toy", "-p", "sizes", "[5]"]) == 2
    assert "parameter 'sizes' of toy needs at least 2 item(s), got [5]" in capsys.readouterr().err
    assert no_kernels == []
    assert resolve_parameters("toy", {"sizes": "5,6"})["sizes"] == [5, 6]
    _ranges(root, "[toy]\nn = { min_items = 1 }\n")  # only a list has items
    with pytest.raises(ParameterError, match="expected an inline table of min, max, above, below, got"):
        resolve_parameters("toy")


def test_a_default_out_of_range_is_refused_too(root):
    _ranges(root, "[toy]\nn = { max = 2 }\n")
    with pytest.raises(ParameterError, match="parameter 'n' of toy is out of range: got 3; allowed: n <= 2"):
        resolve_parameters("toy")
    assert resolve_parameters("toy", {"n": 2})["n"] == 2


@pytest.mark.parametrize("text, message", [
    ("[toy]\nm = { min = 1 }\n", r"\[toy\] m: the parameters cell of toy assigns no parameter 'm'"),
    ("[toy]\nlabel = { min = 1 }\n", r"\[toy\] label: a range needs a numeric parameter"),
    ("[toy]\nn = { least = 1 }\n", r"\[toy\] n: expected an inline table of min, max, above, below"),
    ("[toy]\nn = { min = \"1\" }\n", r"\[toy\] n: the bounds must be numbers"),
    ("toy = 1\n", r"\[toy\] must be a table"),
    ("[toy\n", "is not valid TOML"),
])
def test_a_malformed_range_registry_is_refused_naming_the_file(root, text, message):
    _ranges(root, text)
    with pytest.raises(ParameterError, match=message) as info:
        resolve_parameters("toy")
    assert "parameters.toml" in str(info.value)


def test_without_a_registry_no_range_is_checked(root):
    assert parameter_ranges("toy") == {}
    assert resolve_parameters("toy", {"n": "-5"})["n"] == -5


def test_every_experiment_of_the_project_declares_its_natural_ranges(monkeypatch):
    monkeypatch.setenv("THESIS_LAB_PROJECT", str(ROOT))
    natural = re.compile(r"seed|n_.*|.*_(points|counts|sizes|radius|stride)|noise|nu|repeats|max_dim")
    for name in list_experiments():
        defaults = experiment_parameters(name)
        ranges = parameter_ranges(name, defaults=defaults)
        missing = [k for k, v in defaults.items() if natural.fullmatch(k) and not isinstance(v, str)
                   and k not in ranges]
        assert missing == [], (name, missing)
        resolve_parameters(name)  # every default lies in its range
    assert parameter_ranges("two-circles-landmarks")["n_trials"] == {"min": 1}
    assert parameter_ranges("range-patches")["top"] == {"above": 0, "max": 1}


def test_n_trials_zero_of_the_project_is_refused_before_a_kernel(monkeypatch, capsys, no_kernels):
    monkeypatch.delenv("THESIS_LAB_PROJECT", raising=False)
    argv = ["--project", str(ROOT), "run", "two-circles-landmarks", "-p", "n_trials", "0"]
    assert lab_cli.main(argv) == 2
    assert "error: parameter 'n_trials' of two-circles-landmarks is out of range: got 0; allowed: n_trials >= 1" \
        in capsys.readouterr().err
    assert no_kernels == []


# 7. thesis-lab list prints floats compactly, never changing the stored values


def test_list_prints_floats_compactly(root, capsys):
    set_default(root, "toy", "x", "0.7853981633974483")
    set_default(root, "toy", "sleep", "2.0")
    set_default(root, "toy", "output_mb", "1e-07")
    assert lab_cli.main(["list"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("toy: n=3, x=0.785398, label='a', flag=False, sizes=[60, 100], fail=False, sleep=2.0, ")
    assert "output_mb=1e-07" in out and "0.7853981633974483" not in out
    params = resolve_parameters("toy")
    assert params["x"] == 0.7853981633974483  # the value itself keeps every digit
    assert run_hash(params) != run_hash({**params, "x": 0.785398})
    assert lab_cli._display([0.1, 1e20, 3.0, 12345678.0, True, "s"]) == "[0.1, 1e+20, 3.0, 1.23457e+07, True, 's']"
