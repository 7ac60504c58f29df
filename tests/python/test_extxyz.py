"""snapshots.extxyz (the `snapshots` observable, realization 0) parsed back: one frame per snapshot
time with Lattice/Time in the comment line, every particle once by id, the impurity count, and the
kinetic energy from the velocities equal to E (elastic collisions conserve it; the CLI checks 1e-12);
and read by ASE as a user does: get_masses, get_velocities, no particle taken for an element."""
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
        assert list(columns) == ["Z", "type_name", "typeid", "id", "pos", "velo", "momenta", "masses", "radius",
                                 "moving", "collisions"]
        assert len(rows) == particles
        names = np.array([r[1] for r in rows])
        assert np.count_nonzero(names == "impurity") == 3 and set(names) == {"host", "impurity"}
        table = np.array([[r[0]] + r[2:] for r in rows], dtype=float)  # every column but type_name
        Z, typeid, ids = table[:, 0], table[:, 1], table[:, 2]
        assert not Z.any() and (typeid == (names == "impurity")).all()
        assert (np.diff(ids) > 0).all()  # every particle once, ascending
        pos, velo, momenta, m = table[:, 3:6], table[:, 6:9], table[:, 9:12], table[:, 12]
        if d == 2:
            assert not pos[:, 2].any() and not velo[:, 2].any()
        assert (m[names == "impurity"] == mass).all() and (m[names == "host"] == 1.0).all()
        np.testing.assert_array_equal(momenta, m[:, None] * velo)
        energy = 0.5 * np.sum(m * np.sum(velo**2, axis=1))
        assert energy == pytest.approx(E, rel=1e-12)
        moving, collisions = table[:, 14], table[:, 15]
        assert ((collisions > 0) <= (moving > 0) | (names == "impurity")).all()  # a collided particle has moved
        assert (velo[moving == 0] == 0).all()
    # The moving particles of the last frame match snapshot_20.csv of the same realization.
    csv = coldblast.read_run(tmp_path).snapshots[20.0]
    assert int(csv.moving.sum()) == int(np.array([r[15] for r in parsed[-1][1]], dtype=int).sum())
    np.testing.assert_array_equal(csv.id, np.array([r[3] for r in parsed[-1][1]], dtype=int))


@pytest.mark.parametrize("d", [2, 3])
def test_extxyz_reads_in_ase(tmp_path, d):
    """ASE's own extended-XYZ reader (Debian's python3-ase, as users read the file): every frame, the
    cell, Time, no particle taken for an element (Z = 0: ASE's dummy X), get_masses() and
    get_velocities() from the masses and momenta columns, the ids, and the energy = E."""
    ase_io = pytest.importorskip("ase.io", reason="python3-ase is not installed (scripts/bootstrap.sh installs it)")
    times = [5.0, 20.0]
    E, mass = 4.0, 2.5
    run = coldblast.md.run(realizations=1, out=tmp_path, progress=False, d=d, E=E, t_max=20, box_margin=6,
                           snapshot_times=times, snapshot_particles="all", observables=["R", "snapshots"],
                           impurities={"count": 2, "mass": mass})
    frames = ase_io.read(str(tmp_path / "snapshots.extxyz"), index=":", format="extxyz")
    assert len(frames) == len(times)
    side = 2 * run.summary["region_radius"]
    for atoms, t in zip(frames, times):
        assert len(atoms) == run.summary["particles"]
        assert float(atoms.info["Time"]) == t and atoms.info["run_id"] == run.summary["run_id"]
        assert not atoms.pbc.any()
        np.testing.assert_array_equal(atoms.cell.lengths()[:d], [side] * d)
        assert set(atoms.get_chemical_symbols()) == {"X"}  # no hydrogen, no iodine
        impurity = atoms.arrays["type_name"] == "impurity"
        assert np.count_nonzero(impurity) == 2 and (atoms.arrays["typeid"] == impurity).all()
        masses = atoms.get_masses()
        assert (masses[impurity] == mass).all() and (masses[~impurity] == 1.0).all()
        velocities = atoms.get_velocities()
        np.testing.assert_allclose(velocities, atoms.arrays["velo"], rtol=1e-15, atol=0)
        assert (np.diff(atoms.arrays["id"]) > 0).all()
        if d == 2:
            assert not atoms.positions[:, 2].any()
        assert 0.5 * np.sum(masses * np.sum(velocities**2, axis=1)) == pytest.approx(E, rel=1e-12)
        assert atoms.get_kinetic_energy() == pytest.approx(E, rel=1e-12)
