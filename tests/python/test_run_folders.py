"""One run per folder from Python (docs/md-output.md, "Run ids"): read_run refuses a folder whose
files belong to different runs, naming the file; md.run refuses another run's folder unless
overwrite=True, which replaces exactly that run's files; the run id is in the summary and manifest."""
import json
import shutil

import pytest

import coldblast


def small_run(out, **keys):
    return coldblast.md.run(realizations=2, t_max=20, block_size=1, out=out, progress=False, **keys)


def test_read_run_refuses_a_mixed_folder(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    run = small_run(a)
    small_run(b, E=20)
    assert json.loads((a / "manifest.json").read_text())["run_id"] == run.summary["run_id"]
    assert coldblast.read_run(a).summary["run_id"] == run.summary["run_id"]
    shutil.copy(b / "blocks.csv", a / "blocks.csv")
    with pytest.raises(ValueError, match=r"RUN_DIR: .*/a/blocks\.csv belongs to run .*mixes the files of different runs"):
        coldblast.read_run(a)


def test_md_run_refuses_another_runs_folder_unless_overwrite(tmp_path):
    out = tmp_path / "run"
    first = small_run(out, observables=["R_imp", "snapshots"], snapshot_times=[10.0])
    (out / "notes.txt").write_text("mine\n")
    with pytest.raises(ValueError, match=r"out = .* holds the files of run " + first.summary["run_id"]):
        small_run(out)
    assert (out / "snapshot_10.csv").exists()
    second = small_run(out, overwrite=True)
    assert second.summary["run_id"] != first.summary["run_id"]
    assert not (out / "snapshot_10.csv").exists() and (out / "notes.txt").read_text() == "mine\n"
    assert coldblast.read_run(out).summary["run_id"] == second.summary["run_id"]


def test_progress_in_a_log_has_lines_and_no_carriage_return(tmp_path):
    """progress=True with stderr not a terminal (a log, a pipe): plain lines, one per tenth of the
    work, with the elapsed time and the ETA; the CLI's non-terminal stderr is the same."""
    import subprocess
    import sys
    script = "import coldblast; coldblast.md.run(realizations=20, t_max=20, progress=True)"
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert "\r" not in done.stderr
    lines = [line for line in done.stderr.splitlines() if line.startswith("md run: ")]
    assert lines[-1].startswith("md run: 20/20 realizations (100 %), ") and " elapsed, ETA " in lines[-1]
    assert 1 <= len(lines) <= 11
    from conftest import run_cli
    _, stderr = run_cli("md", "run", "--realizations", 20, "--set", "t_max=20", "--out", tmp_path / "cli")
    assert "\r" not in stderr and "md run: 20/20 realizations (100 %)" in stderr
