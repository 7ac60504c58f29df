"""snapshots.extxyz (the `snapshots` observable, realization 0) parsed back: one frame per snapshot
time with Lattice/Time in the comment line, every particle, the impurity count, and the kinetic
energy from the velocities equal to E (elastic collisions conserve it; the CLI checks 1e-12)."""
import re

import numpy as np
import pytest

import coldblast


def frames(path):
    lines = open(path).read().splitlines()
    i, out = 0, []
    while i < len(lines):
        n = int(lines[i])
        comment = lines[i + 1]
        rows = [line.split() for line in lines[i + 2:i + 2 + n]]
        out.append((comment, rows))
        i += 2 + n
    return out


def properties(comment):
    spec = re.search(r"Properties=(\S+)", comment).group(1).split(":")
    columns, k = {}, 0
    for name, kind, width in zip(spec[0::3], spec[1::3], spec[2::3]):
        columns[name] = (k, int(width), kind)
        k += int(width)
    return columns


@pytest.mark.parametrize("d,E,mass", [(2, 10.0, 1.0), (3, 6.0, 3.0)])
def test_extxyz_frames(tmp_path, d, E, mass):
    times = [5.0, 10.0, 20.0]
    run = coldblast.md.run(realizations=1, out=tmp_path, progress=False, d=d, E=E, t_max=20, n=0.15 if d == 2 else 0.1, box_margin=6,
                           snapshot_times=times, snapshot_particles="all", observables=["R", "snapshots"],
                           impurities={"count": 3, "mass": mass})
    parsed = frames(tmp_path / "snapshots.extxyz")
    assert len(parsed) == len(times)
    particles = run.summary["particles"]
    for (comment, rows), t in zip(parsed, times):
        assert float(re.search(r"Time=(\S+)", comment).group(1)) == t
        lattice = np.array(re.search(r'Lattice="([^"]+)"', comment).group(1).split(), dtype=float).reshape(3, 3)
        assert lattice[0, 0] == lattice[1, 1] == 2 * run.summary["region_radius"] and lattice[2, 2] > 0
        assert np.count_nonzero(lattice - np.diag(np.diag(lattice))) == 0
        columns = properties(comment)
        assert list(columns) == ["species", "pos", "velo", "mass", "radius", "moving", "collisions"]
        assert len(rows) == particles
        species = np.array([r[0] for r in rows])
        assert np.count_nonzero(species == "I") == 3 and set(species) == {"H", "I"}
        table = np.array([r[1:] for r in rows], dtype=float)
        pos, velo, m = table[:, 0:3], table[:, 3:6], table[:, 6]
        if d == 2:
            assert not pos[:, 2].any() and not velo[:, 2].any()
        assert (m[species == "I"] == mass).all() and (m[species == "H"] == 1.0).all()
        energy = 0.5 * np.sum(m * np.sum(velo**2, axis=1))
        assert energy == pytest.approx(E, rel=1e-12)
        moving, collisions = table[:, 8], table[:, 9]
        assert ((collisions > 0) <= (moving > 0) | (species == "I")).all()  # a collided particle has moved
        assert (velo[moving == 0] == 0).all()
    # The moving particles of the last frame match snapshot_20.csv of the same realization.
    csv = coldblast.read_run(tmp_path).snapshots[20.0]
    assert int(csv["moving"].sum()) == int(np.array([r[9] for r in parsed[-1][1]], dtype=int).sum())


@pytest.mark.parametrize("d", [2, 3])
def test_extxyz_reads_in_ase(tmp_path, d):
    """ASE's own extended-XYZ reader (Debian's python3-ase, as viewers read the file): every frame,
    the cell, Time, the species, positions and the custom velo/mass columns."""
    ase_io = pytest.importorskip("ase.io", reason="python3-ase is not installed (scripts/bootstrap.sh installs it)")
    times = [5.0, 20.0]
    E = 4.0
    run = coldblast.md.run(realizations=1, out=tmp_path, progress=False, d=d, E=E, t_max=20, box_margin=6,
                           snapshot_times=times, snapshot_particles="all", observables=["R", "snapshots"],
                           impurities={"count": 2})
    frames = ase_io.read(str(tmp_path / "snapshots.extxyz"), index=":", format="extxyz")
    assert len(frames) == len(times)
    side = 2 * run.summary["region_radius"]
    for atoms, t in zip(frames, times):
        assert len(atoms) == run.summary["particles"]
        assert float(atoms.info["Time"]) == t
        assert not atoms.pbc.any()
        np.testing.assert_array_equal(atoms.cell.lengths()[:d], [side] * d)
        assert atoms.get_chemical_symbols().count("I") == 2
        if d == 2:
            assert not atoms.positions[:, 2].any()
        velo, mass = atoms.arrays["velo"], atoms.arrays["mass"]
        assert 0.5 * np.sum(mass * np.sum(velo**2, axis=1)) == pytest.approx(E, rel=1e-12)
