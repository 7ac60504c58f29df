"""The analysis scripts (scripts/*.py) against independent paths: what they compute from blocks.csv
with block-jackknife errors (recollision_energy.py, energy_budget.py, bow_figure.py) equals the same
quantities from observables.csv's means, and the shared jackknife (block_jackknife.py) its closed
form for a mean."""
import csv
import io
import os
import re
import subprocess
import sys

import pytest

from conftest import REPO

HEAVY = os.path.join(REPO, "data", "recollisions", "heavy")


def means(directory):
    rows = [r for r in open(os.path.join(directory, "observables.csv")) if not r.startswith("#")]
    return {(float(r["t"]), r["observable"]): float(r["mean"]) for r in csv.DictReader(io.StringIO("".join(rows)))}


def test_energy_per_collision_equals_the_means_ratio():
    out = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "recollision_energy.py"), HEAVY],
                         capture_output=True, text=True, check=True).stdout
    m = means(HEAVY)
    windows = re.findall(r"t in \(([0-9.e+]+), ([0-9.e+]+)\]: energy lost per first collision ([-0-9.e]+) ± [0-9.e-]+, "
                         r"per recollision ([-0-9.e]+) ± [0-9.e-]+, ratio ([-0-9.e]+) ± ([0-9.e-]+)", out)
    assert len(windows) == 3, out
    for t1, t2, first, re_, ratio, ratio_error in windows:
        t1, t2 = float(t1), float(t2)
        def change(name):
            return m[(t2, name)] - (0.0 if t1 == 0 else m[(t1, name)])
        expected_first = change("dE_first") / (change("C_imp") - change("C_re"))
        expected_re = change("dE_re") / change("C_re")
        assert abs(float(first) / expected_first - 1) < 1e-3  # printed to 4 digits
        assert abs(float(re_) / expected_re - 1) < 1e-3
        assert abs(float(ratio) - expected_re / expected_first) < 1e-3
        assert 0 < float(ratio_error) < 0.1
    # the heavy projectile's recollisions take about two thirds of a first collision's share early on
    assert 0.6 < float(windows[0][4]) < 0.7


def test_figure_and_shares(tmp_path):
    figure = tmp_path / "recollisions.png"
    subprocess.run([sys.executable, os.path.join(REPO, "scripts", "recollision_energy.py"), "--figure", str(figure),
                    HEAVY], capture_output=True, text=True, check=True)
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import recollision_energy
    t, value, error = recollision_energy.shares(HEAVY)
    m = means(HEAVY)
    assert t[-1] == 4000.0
    assert abs(value[0][-1] - m[(4000.0, "C_re")] / m[(4000.0, "C_imp")]) < 1e-12
    lost = m[(4000.0, "dE_first")] + m[(4000.0, "dE_re")]
    assert abs(value[1][-1] - m[(4000.0, "dE_re")] / lost) < 1e-12
    assert 0 < error[0][-1] < 0.01 and 0 < error[1][-1] < 0.01  # 256 realizations: errors of a few 1e-3



def test_energy_budget_two_paths_agree():
    """scripts/energy_budget.py: first collisions are C_imp − C_re of observables.csv's means, and the
    energy lost from dE_first + dE_re (MD runs) equals the one from V_imp (how tracer runs are read):
    the impurities change their energy only in collisions."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import energy_budget
    rows = energy_budget.budget(HEAVY, [250.0, 1000.0, 4000.0])
    assert [(t1, t2) for t1, t2, _, _ in rows] == [(250.0, 1000.0), (1000.0, 4000.0)]
    m = means(HEAVY)
    sums, counts = energy_budget.block_sums(HEAVY)
    count = sum(counts.values())
    for t1, t2, value, error in rows:
        def change(name):
            return m[(t2, name)] - m[(t1, name)]
        assert abs(value[0] - (change("C_imp") - change("C_re"))) < 1e-10
        assert abs(value[1] - change("C_re")) < 1e-10
        assert abs(value[2] - (change("dE_first") + change("dE_re"))) < 1e-12
        assert abs(value[3] - change("dE_first") / (change("C_imp") - change("C_re"))) < 1e-12
        assert all(0 < e < 0.2 * abs(v) for v, e in zip(value, error))
        # the V_imp path, as for a tracer run (no dE_first): the same energy to round-off
        stripped = {b: {k: x for k, x in block.items() if k[1] in ("C_imp", "V_imp")} for b, block in sums.items()}
        lost = sum(energy_budget.window_sums(block, t1, t2, 10.0)[2] for block in stripped.values()) / count
        assert abs(lost - value[2]) < 1e-9 * value[2]
    out = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "energy_budget.py"), "--windows", "250,4000",
                          HEAVY], capture_output=True, text=True, check=True).stdout
    assert "t in (250, 4000]: first collisions" in out, out


def test_bow_figure_equals_the_means(tmp_path):
    """scripts/bow_figure.py: g_front/g_back and u_front/(sqrt(2) V_imp) from blocks.csv equal the
    same ratios of observables.csv's means; the figure is drawn."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import bow_figure
    shells = os.path.join(REPO, "data", "recollisions", "heavy-shells")
    t, value, error = bow_figure.bow(shells)
    m = means(shells)
    for k in (20, 32, len(t) - 1):
        assert abs(value[0][k] - m[(t[k], "g_front")] / m[(t[k], "g_back")]) < 1e-12
        assert abs(value[1][k] - m[(t[k], "u_front")] / (2 ** 0.5 * m[(t[k], "V_imp")])) < 1e-12
        assert 0 < error[0][k] < 0.5 and 0 < error[1][k] < 0.1
    assert value[0][t.tolist().index(250.0)] > 1.5  # the heavy impurity's bow (docs/verification.md)
    figure = tmp_path / "bow.png"
    subprocess.run([sys.executable, os.path.join(REPO, "scripts", "bow_figure.py"), str(figure), shells],
                   capture_output=True, text=True, check=True)
    assert figure.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_block_jackknife_of_a_mean_is_the_standard_error():
    """scripts/block_jackknife.py: for the mean of equal blocks, the delete-one-block jackknife error
    is exactly the standard error of the block means (its closed form)."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import numpy as np
    from block_jackknife import jackknife
    rng = np.random.default_rng(7)
    parts = [rng.normal(size=3) * 4 + 10 for _ in range(25)]  # sums over 4 realizations each
    value, error = jackknife(parts, [4.0] * 25, lambda x, count: x / count)
    means = np.array(parts) / 4
    assert np.allclose(value, means.mean(axis=0), rtol=1e-14)
    assert np.allclose(error, means.std(axis=0, ddof=1) / np.sqrt(25), rtol=1e-12)


def test_code_sizes_lists_every_module_with_its_largest_file():
    out = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "code_sizes.py"), "--limit", "40", REPO],
                         capture_output=True, text=True, check=True).stdout
    rows = re.findall(r"^\| (\w+) \| (\S+) \((\d+)\) \| (\S+) in (\S+):(\d+) \((\d+)(?:, data table)?\) \|$", out,
                      flags=re.M)
    assert [r[0] for r in rows] == ["common", "theory", "hydro", "md", "run", "kinetic", "compare", "cli", "python"]
    for module, largest, lines, _, where, first, length in rows:
        folder = os.path.join(REPO, module)
        counts = {name: sum(1 for _ in open(os.path.join(folder, name), encoding="utf-8"))
                  for name in os.listdir(folder) if name.endswith((".cpp", ".hpp"))}
        assert int(lines) == max(counts.values()) == counts[os.path.basename(largest)], module
        assert where.startswith(module + "/") and int(first) >= 1
    # Every function over the limit is listed, longest first, data tables (marked in the table) apart,
    # and the modules' longest is among them.
    code, tables = out.split("\ndata tables over 40 lines: ")
    assert "functions over 40 lines outside data tables: " in code
    longest = 0
    for part in (code, tables):
        listed = [int(n) for n in re.findall(r"^ +(\d+)  ", part, flags=re.M)]
        assert listed == sorted(listed, reverse=True) and all(n > 40 for n in listed)
        longest = max([longest] + listed)
    assert max(int(r[6]) for r in rows) == longest
    assert "observable_catalogue  theory/observables.cpp" in tables


def scaled_run(source, target, factors):
    """A copy of run `source` (blocks.csv, p_imp.csv) with the inner sums of observables scaled:
    factors {name: f} multiply every block's sum of that name."""
    os.makedirs(target)
    with open(os.path.join(source, "blocks.csv")) as f, open(os.path.join(target, "blocks.csv"), "w") as out:
        for line in f:
            if line.startswith("#") or line.startswith("block,"):
                out.write(line)
                continue
            block, t, name, total, count = line.rstrip("\n").split(",")
            out.write(f"{block},{t},{name},{float(total) * factors.get(name, 1.0)!r},{count}\n")
    with open(os.path.join(source, "p_imp.csv")) as f, open(os.path.join(target, "p_imp.csv"), "w") as out:
        out.write(f.read())


def test_tracer_decomposition_adds_up_with_the_jackknife_errors(tmp_path):
    """scripts/tracer_decomposition.py on runs made from the MD's own blocks with R_imp, C_imp scaled
    by known factors (R_imp's inner value is r^2/2, so 1.21 makes R_imp 1.1 times the MD's): the total,
    Eq. (36)'s and the background's parts are the known per cents and add up; the errors are the
    closed forms of the block jackknife for runs that share the MD's noise (paired) and an
    independent MD; p_imp's ratio differences vanish for equal histograms; the figure is drawn."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import numpy as np
    import tracer_decomposition as td
    from block_jackknife import time_series
    md = os.path.join(REPO, "data", "campaign4-heavy")
    ns, fields = str(tmp_path / "ns"), str(tmp_path / "fields")
    scaled_run(md, ns, {"R_imp": 1.1 ** 2, "C_imp": 1.15})
    scaled_run(md, fields, {"R_imp": 1.02 ** 2, "C_imp": 1.05})
    result = td.decomposition(md, ns, fields, [15.625, 250.0, 4000.0])
    assert result["times"] == [15.625, 250.0, 4000.0]
    assert all(result["paired"].values())
    t, value, error = time_series(md, ["R_imp"], lambda x, count: np.sqrt(x / count))
    for name, (total, own) in (("R_imp", (10.0, 2.0)), ("C_imp", (15.0, 5.0)), ("V_imp", (0.0, 0.0))):
        for t_k, tot, tot_e, o, o_e, bg, bg_e, m, dm in result[name]:
            assert abs(tot - total) < 1e-9 and abs(o - own) < 1e-9 and abs(bg - (total - own)) < 1e-9
            assert abs(tot - (o + bg)) < 1e-9
            relative = dm / m
            assert abs(tot_e - 100 * (1 + total / 100) * np.sqrt(2) * relative) < 1e-9
            assert abs(o_e - 100 * (1 + own / 100) * np.sqrt(2) * relative) < 1e-9
            # paired: (a - b) has the MD's relative noise, (total - own) % of it; MD's independent
            assert abs(bg_e - (total - own) * np.sqrt(2) * relative) < 1e-9
            if name == "R_imp":
                assert abs(dm - error[list(t).index(t_k)][0]) < 1e-12
    for t_k, m, dm, a, da, b, db in result["p_imp"]:
        assert m == a == b and 1.0 < m < 2.0 and 0 < dm < 0.05
    # --variants: a run in other fields, R_imp 1.03 times the MD's, changes by +1 % of the MD from
    # the 1.02 run, its paired error 1 % times the MD's relative error (the runs share the MD's noise).
    variant = str(tmp_path / "variant")
    scaled_run(md, variant, {"R_imp": 1.03 ** 2, "C_imp": 1.05})
    changes = td.variant_changes(md, fields, [variant], [250.0, 4000.0])
    for name, change in (("R_imp", 1.0), ("C_imp", 0.0), ("V_imp", 0.0)):
        for (t_k, [(c, e)]), row in zip(changes[name], [r for r in result[name] if r[0] in (250.0, 4000.0)]):
            assert abs(c - change) < 1e-9 and abs(e - change * row[8] / row[7]) < 1e-9
    assert all(c == 0.0 for t_k, [(c, e)] in changes["p_imp"])
    out = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "tracer_decomposition.py"), md, ns, fields,
                          "--times", "250,4000", "--figure", str(tmp_path / "d.png"), "--variants", variant],
                         capture_output=True, text=True, check=True).stdout
    assert "| 4000 |" in out and "+10.0 ± " in out and "paired jackknife" in out
    assert "| t | variant |" in out and "| 4000 | +1.00 ± " in out
    assert (tmp_path / "d.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # A tracer's own start time is no measurement (its R_imp and C_imp count from there): left out.
    with open(os.path.join(fields, "summary.json"), "w") as f:
        f.write('{"start_time": 250.0}')
    assert td.decomposition(md, ns, fields, [15.625, 250.0, 4000.0])["times"] == [4000.0]


def test_profile_variants_keep_mass_momentum_and_energy_and_perturb_by_the_errors(tmp_path):
    """scripts/profile_variants.py merges bins as md run bins particles: per kept time the mass
    (density x shell volume), the radial momentum (particles x u) and the kinetic energy
    (particles x (d T + u^2)) of the merged bins equal the original bins'; every second time is
    kept; merging nothing reproduces the file. --noise moves every bin by deviates whose
    distribution, in units of the stated errors, has mean 0 and variance 1."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import profile_variants
    md = os.path.join(REPO, "data", "campaign1-paper-2d")
    _, rows = profile_variants.read(os.path.join(md, "profiles.csv"))
    merged = profile_variants.coarsen(rows, 2, 3, 2)
    times = sorted({float(r["t"]) for r in rows})
    assert sorted({float(r["t"]) for r in merged}) == times[::2]
    assert len(merged) == len(times[::2]) * 10
    def totals(table, t):
        part = [r for r in table if float(r["t"]) == t]
        mass = sum(float(r["density_over_n"]) * (float(r["r_over_R_hi"]) ** 2 - float(r["r_over_R_lo"]) ** 2)
                   for r in part)
        momentum = sum(float(r["particles"]) * float(r["radial_velocity"]) for r in part)
        energy = sum(float(r["particles"]) * (2 * float(r["temperature"]) + float(r["radial_velocity"]) ** 2)
                     for r in part)
        return mass, momentum, energy
    for t in (times[0], times[20], times[-1]):
        for a, b in zip(totals(rows, t), totals(merged, t)):
            assert abs(a - b) <= 1e-12 * abs(a) + 1e-300
    same = profile_variants.coarsen(rows, 2, 1, 1)
    for a, b in zip(rows, same):
        for key in ("density_over_n", "radial_velocity", "temperature", "particles"):
            assert abs(float(a[key]) - float(b[key])) <= 1e-13 * abs(float(a[key])) + 1e-18
    out = tmp_path / "coarse"
    subprocess.run([sys.executable, os.path.join(REPO, "scripts", "profile_variants.py"), md, str(out),
                    "--bins", "2", "--times", "2"], capture_output=True, text=True, check=True)
    assert (out / "summary.json").exists() and (out / "observables.csv").exists()
    _, written = profile_variants.read(str(out / "profiles.csv"))
    assert len(written) == len(times[::2]) * 15
    import numpy as np
    noisy = profile_variants.perturb(rows, 2, 30000, 7)
    z = {"density_over_n": [], "radial_velocity": [], "temperature": []}
    for a, b in zip(rows, noisy):
        count, T = float(a["particles"]) * 30000, float(a["temperature"])
        if count < 100 or T <= 0:
            continue
        errors = {"density_over_n": float(a["density_stderr"]), "radial_velocity": (T / count) ** 0.5,
                  "temperature": T * (2 / (2 * count)) ** 0.5}
        for key, e in errors.items():
            z[key].append((float(b[key]) - float(a[key])) / e)
    for key, values in z.items():
        values = np.array(values)
        assert len(values) > 1000
        assert abs(values.mean()) < 4 / len(values) ** 0.5 and abs(values.var() - 1) < 0.15, key


def test_start_memory_figure_draws_the_tables_numbers(tmp_path):
    """scripts/start_memory_figure.py reads scripts/start_memory.py's tables as written (the
    differences in per cent, the NS column where there is one, p_imp's ratios), refuses a label count
    that does not match, and draws the PNG."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import start_memory_figure as smf
    folder = os.path.join(REPO, "data", "start-memory")
    hot, single = os.path.join(folder, "start_memory.csv"), os.path.join(folder, "start_memory_single.csv")
    tables = [smf.read_table(hot), smf.read_table(single)]
    with open(hot) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    first = next(r for r in rows if r["amplitude"] == "n0/n")
    x, kick, kick_e, other, other_e, delta, delta_e, ns = tables[0]["n0/n"][0]
    assert (x, delta, delta_e) == (float(first["R_over_lambda"]), float(first["delta"]), float(first["delta_err"]))
    assert ns == float(first["ns_delta"]) and tables[1]["n0/n"][0][7] is None  # the single start has no NS partner
    files = smf.write_data(str(tmp_path), tables)
    with open(files[(0, "n0/n")]) as f:
        values = [float(v) for v in f.readline().split()]
    assert values == [x, 100 * delta, 100 * delta_e, 100 * ns]
    with open(files[(1, "p_imp_ratio")]) as f:
        values = [float(v) for v in f.readline().split()]
    ratio = tables[1]["p_imp_ratio"][0]
    assert values == [ratio[0], ratio[1], ratio[2], ratio[3], ratio[4]]
    script = os.path.join(REPO, "scripts", "start_memory_figure.py")
    bad = subprocess.run([sys.executable, script, hot, single, "--labels", "one", "--out", str(tmp_path / "x.png")],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "--labels: 1 given for 2 tables" in bad.stderr and not (tmp_path / "x.png").exists()
    out = subprocess.run([sys.executable, script, hot, single, "--labels", "hot spot", "single", "--out",
                          str(tmp_path / "m.png")], capture_output=True, text=True, check=True).stdout
    assert "2 starts against the kick, R/λ from 10 to 34.7" in out
    assert (tmp_path / "m.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_amplitude_history_figure_draws_the_files_numbers(tmp_path):
    """scripts/amplitude_history_figure.py reads compare's amplitudes.csv as written (MD/NS - 1 and its
    error in per cent, the bound, only from --from on), refuses a label count that does not match,
    and draws the PNG and the PDF."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import amplitude_history_figure as ahf
    path = os.path.join(REPO, "data", "amplitude-history", "campaign2-2d-long.csv")
    with open(path) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#")) if r["amplitude"] == "H/R"]
    table = ahf.read_history(path, 0.0)
    assert len(table["H/R"]) == len(rows)
    first = min(rows, key=lambda r: float(r["R_over_lambda"]))
    assert table["H/R"][0] == (float(first["R_over_lambda"]), 100 * float(first["md_over_ns_minus_1"]),
                               100 * float(first["md_over_ns_minus_1_stderr"]), 100 * float(first["continuum_bound"]))
    late = ahf.read_history(path, 25.0)
    assert min(x for x, *_ in late["H/R"]) >= 25.0 and len(late["H/R"]) < len(rows)
    script = os.path.join(REPO, "scripts", "amplitude_history_figure.py")
    bad = subprocess.run([sys.executable, script, path, path, "--labels", "one", "--out", str(tmp_path / "x.png")],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "--labels: give one label per CSV" in bad.stderr
    assert not (tmp_path / "x.png").exists()
    subprocess.run([sys.executable, script, path, "--labels", "campaign 2", "--out", str(tmp_path / "h.png"),
                    "--from", "25"], capture_output=True, text=True, check=True)
    assert (tmp_path / "h.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "h.pdf").read_bytes()[:5] == b"%PDF-"


def test_replication_compares_nearest_times_in_combined_sigma(tmp_path):
    """scripts/replication.py reads two amplitudes.csv as compare writes them, picks each file's
    recorded R/λ nearest to --at, and prints (a - b)/sqrt(σa² + σb²): here (0.05 - 0.01)/0.05 = +0.8σ
    from a 3-4-5 triangle of errors; a bad --at is refused."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import replication
    head = "# comment\nt,R_over_lambda,amplitude,md_over_ns_minus_1,md_over_ns_minus_1_stderr\n"
    (tmp_path / "a.csv").write_text(head + "1,99,H/R,0.05,0.03\n2,300,H/R,0.0,0.01\n")
    (tmp_path / "b.csv").write_text(head + "1,102,H/R,0.01,0.04\n2,310,H/R,0.02,0.01\n")
    a, b = replication.read(str(tmp_path / "a.csv")), replication.read(str(tmp_path / "b.csv"))
    assert replication.nearest(a, 100) == 99 and replication.nearest(b, 100) == 102
    assert abs(replication.difference(a[(99, "H/R")], b[(102, "H/R")]) - 0.8) < 1e-12
    out = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "replication.py"), str(tmp_path / "a.csv"),
                          str(tmp_path / "b.csv"), "--at", "100", "307", "--amplitudes", "H/R"],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[2] == "| 99 | H/R | +5.00 ± 3.00 | +1.00 ± 4.00 | +0.8 |"
    assert out[3] == "| 300 | H/R | +0.00 ± 1.00 | +2.00 ± 1.00 | −1.4 |"
    # --pooled: the inverse-variance mean, (0.05/9 + 0.01/16)/(1/9 + 1/16) = 0.0356 ± (1/9 + 1/16)^(-1/2) = 0.024
    assert replication.pooled((0.05, 0.03), (0.01, 0.04)) == pytest.approx((0.0356, 0.024), rel=1e-12)
    out = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "replication.py"), str(tmp_path / "a.csv"),
                          str(tmp_path / "b.csv"), "--at", "100", "--amplitudes", "H/R", "--pooled"],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[0].endswith("| difference (σ) | pooled |") and out[1] == "|---|---|---|---|---|---|"
    assert out[2] == "| 99 | H/R | +5.00 ± 3.00 | +1.00 ± 4.00 | +0.8 | +3.56 ± 2.40 |"
    bad = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "replication.py"), str(tmp_path / "a.csv"),
                          str(tmp_path / "b.csv"), "--at", "0"], capture_output=True, text=True)
    assert bad.returncode == 2 and "--at: each R/λ must be > 0" in bad.stderr
    missing = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "replication.py"),
                              str(tmp_path / "a.csv"), str(tmp_path / "none.csv")], capture_output=True, text=True)
    assert missing.returncode == 2 and "none.csv: No such file or directory" in missing.stderr
    (tmp_path / "empty.csv").write_text(head)
    empty = subprocess.run([sys.executable, os.path.join(REPO, "scripts", "replication.py"),
                            str(tmp_path / "empty.csv"), str(tmp_path / "b.csv")], capture_output=True, text=True)
    assert empty.returncode == 2 and "empty.csv: no rows" in empty.stderr


def test_amplitude_history_layout_keeps_the_legend_on_the_canvas():
    """The legend of scripts/amplitude_history_figure.py takes the first free slot of the panel grid,
    or its own strip under the title when the panels fill the grid (6 of 3 × 2: it was once drawn off
    the canvas there). For 1 to 9 panels the legend lies inside [0, 1]² and overlaps no panel."""
    sys.path.insert(0, os.path.join(REPO, "scripts"))
    import amplitude_history_figure as ahf
    for n in range(1, 10):
        rows, height, (lx, ly), (lw, lh) = ahf.layout(n, 3)
        assert rows == (n + 2) // 3
        assert 0 <= lx and lx + lw <= 1 + 1e-12 and 0 <= ly and ly + lh <= ahf.TOP + 1e-12, n
        for k in range(n):
            px, py = (k % 3) / 3, (rows - 1 - k // 3) * height
            overlap_x = min(px + 1 / 3, lx + lw) - max(px, lx)
            overlap_y = min(py + height, ly + lh) - max(py, ly)
            assert overlap_x <= 1e-12 or overlap_y <= 1e-12, (n, k)
            assert py >= -1e-12 and py + height <= ahf.TOP + 1e-12
    # the panels fill the space under the title (and the legend's strip), leaving no gap
    assert ahf.TOP <= 0.95
    assert abs(ahf.layout(6, 3)[1] * 2 + ahf.LEGEND_STRIP - ahf.TOP) < 1e-12
    assert ahf.layout(6, 3)[3] == (1.0, ahf.LEGEND_STRIP) and ahf.layout(5, 3)[2] == (2 / 3, 0.0)


def test_campaign_tables_select_and_format_what_compare_wrote(tmp_path):
    """scripts/campaign_tables.py prints compare's own numbers: the last time's amplitudes with
    their verdicts, MD/NS - 1 at the recorded R/λ nearest to --at (errors to two significant figures),
    and the tracer's ratio in both backgrounds; without the tracer folders only the amplitude tables;
    a missing folder or a bad --at is refused with exit code 2."""
    head = ("# comment\nt,R_over_lambda,amplitude,md,md_stderr,ns,md_over_ns_minus_1,"
            "md_over_ns_minus_1_stderr,deviation_sigma,continuum_bound,verdict\n")
    (tmp_path / "c" / "vs-hydro").mkdir(parents=True)
    (tmp_path / "c" / "vs-hydro" / "amplitudes.csv").write_text(
        head + "100,10,H/R,0.5,0.01,0.52,-0.0384615,0.0192,-2.0,0.5,miss\n"
        "400,20,H/R,0.42,0.0043,0.45,-0.0666667,0.00956,-6.98,0.3,miss\n"
        "400,20,T0/Rdot^2,1.383,0.061,1.3733,0.00706,0.0445,0.16,0.3,pass\n")
    script = [sys.executable, os.path.join(REPO, "scripts", "campaign_tables.py")]
    out = subprocess.run(script + [str(tmp_path / "c"), "--at", "9", "30"],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[0] == "At t = 400 (R/λ = 20.0):"
    assert out[4] == "| H/R | 0.4200 ± 0.0043 | −6.67 % (−7.0) | miss | 0.45 |"
    assert out[5] == "| T0/Ṙ² (100-particle ball) | 1.383 ± 0.061 | +0.71 % (+0.2) | pass | 1.3733 |"
    assert out[9] == "| R/λ | 10.0 | 20.0 |"
    assert out[11] == "| H/R | −3.8 ± 1.9 | −6.67 ± 0.96 |"
    assert out[12] == "| T0/Ṙ² (100-particle ball) | – | +0.7 ± 4.5 |"
    assert len(out) == 13  # no tracer folders: no tracer table
    tracer_head = "# c\nt,observable,tracer,tracer_stderr,md,md_stderr,ratio_minus_1,ratio_minus_1_stderr\n"
    for name, ratio in (("tracer-vs-md", "0.264"), ("tracer-mdfields-vs-md", "0.061")):
        (tmp_path / "c" / name).mkdir()
        (tmp_path / "c" / name / "tracer_vs_md.csv").write_text(tracer_head + f"398,C_imp,1,0,1,0,{ratio},0.021\n")
    out = subprocess.run(script + [str(tmp_path / "c"), "--times", "400"],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    assert out[-1] == "| 398 | 20 | +0.264 ± 0.021 | +0.061 ± 0.021 | – | – | – | – |"
    bad = subprocess.run(script + [str(tmp_path / "c"), "--at", "0"], capture_output=True, text=True)
    assert bad.returncode == 2 and "--at and --times: each value must be > 0" in bad.stderr
    missing = subprocess.run(script + [str(tmp_path / "none")], capture_output=True, text=True)
    assert missing.returncode == 2 and "none/vs-hydro/amplitudes.csv: No such file or directory" in missing.stderr
