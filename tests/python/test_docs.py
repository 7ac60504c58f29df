"""docs/python.md is executed: its ```python blocks run in order, in one namespace, in a scratch
folder where `scenes/` points to the repository's scenes (the page assumes the repository root)."""
import os
import re
import time

from conftest import REPO


def test_python_md_runs(tmp_path, monkeypatch):
    with open(os.path.join(REPO, "docs", "python.md")) as f:
        blocks = re.findall(r"```python\n(.*?)```", f.read(), flags=re.S)
    assert len(blocks) >= 3
    os.symlink(os.path.join(REPO, "scenes"), tmp_path / "scenes")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    start = time.monotonic()
    for block in blocks:
        exec(compile(block, "docs/python.md", "exec"), namespace)
    print(f"docs/python.md ran in {time.monotonic() - start:.1f} s")
    assert (tmp_path / "fig2.png").stat().st_size > 20000
    assert namespace["run"].summary["realizations"] == 64
    # The snapshot section: arrays of the one realization, the farthest moving particle at the shock.
    snap, R = namespace["snap"], namespace["one"].estimate("R")["mean"].iloc[-1]
    assert snap.position.shape == (len(snap), 2) and snap.impurity.sum() == 4
    assert 0.9 * R < namespace["radius"].max() < 1.15 * R  # a few particles run ahead of the shock
    # The tour's verdict holds the six Table 1 observables, each with a finite running exponent.
    names = [v["name"] for v in namespace["verdict"]["observables"]]
    # The tracer section compares R_imp, V_imp and C_imp with the tour's MD run at its last time.
    tracer_names = {o["name"] for o in namespace["against_md"]["observables"]}
    assert {"R_imp", "V_imp", "C_imp"} <= tracer_names
    assert namespace["tracer"].summary["trajectories"] == 4000
    assert sorted(names) == sorted(["R_imp", "V_imp", "C_imp", "u_imp", "n0", "T0"])
    # The hydro verdict's amplitude history: every recorded time from R/λ = 10 to the last one.
    history = namespace["history"]
    assert history.R_over_lambda.min() >= 10 and history.t.max() == namespace["hydro"]["until"]
    assert set(history.name) == {"n0/n", "T0/Rdot^2", "R"}  # the tour records no profiles: no H, no centre


def test_campaign_tables_in_the_docs_are_the_datas():
    """Every `scripts/campaign_tables.py ...` and `scripts/replication.py ...` command that
    docs/verification.md shows on a line of its own is run, and every table row it prints must be a
    line of the page: the campaign tables there are data/'s numbers, not retyped ones."""
    import shlex
    import subprocess
    import sys
    with open(os.path.join(REPO, "docs", "verification.md")) as f:
        text = f.read()
    lines = {line.strip() for line in text.splitlines()}
    commands = re.findall(r"^(scripts/(?:campaign_tables|replication)\.py .*)$", text, flags=re.M)
    assert {c.split()[0] for c in commands} == {"scripts/campaign_tables.py", "scripts/replication.py"}
    for command in commands:
        argv = shlex.split(command)
        out = subprocess.run([sys.executable, os.path.join(REPO, argv[0])] + argv[1:], cwd=REPO,
                             capture_output=True, text=True, check=True).stdout
        rows = [row for row in out.splitlines() if row.startswith("|")]
        assert len(rows) >= 4
        missing = [row for row in rows if row not in lines]
        assert not missing, f"{command}: rows not in docs/verification.md: {missing}"
