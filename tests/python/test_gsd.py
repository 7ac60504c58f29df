"""GSD files of a run's snapshots (coldblast.write_gsd, ``python3 -m coldblast gsd``) read back with
the gsd library's own reader (gsd.hoomd, Debian's python3-gsd) as OVITO, freud and hoomd users read
them: one frame per snapshot, the count, type names and ids, masses, diameters, velocities (float32
as the schema has them; the float64 log copy gives the energy = E to 1e-12), the box, the time and
the run id; bad input exits 2 naming the argument, and a device is never replaced."""
import os
import subprocess
import sys

import numpy as np
import pytest

import coldblast

gsd_hoomd = pytest.importorskip("gsd.hoomd", reason="python3-gsd is not installed (scripts/bootstrap.sh installs it)")


def blast(tmp_path, d, E, mass, stride=1):
    return coldblast.md.run(realizations=1, out=tmp_path / "run", progress=False, d=d, E=E, t_max=20, box_margin=6,
                            snapshot_times=[5.0, 10.0, 20.0], snapshot_stride=stride, observables=["R", "snapshots"],
                            impurities={"count": 3, "mass": mass})


@pytest.mark.parametrize("d,E,mass", [(2, 10.0, 1.0), (3, 6.0, 2.5)])
def test_gsd_round_trip(tmp_path, d, E, mass):
    run = blast(tmp_path, d, E, mass)
    written = coldblast.write_gsd(tmp_path / "run")
    assert written == tmp_path / "run" / "snapshots.gsd"
    csv = coldblast.read_run(tmp_path / "run").snapshots
    with gsd_hoomd.open(str(written), mode="rb") as trajectory:
        assert len(trajectory) == 3
        for index, (frame, t) in enumerate(zip(trajectory, [5.0, 10.0, 20.0])):
            p = frame.particles
            assert frame.configuration.step == index and frame.configuration.dimensions == d
            side = 2 * run.summary["region_radius"]
            np.testing.assert_allclose(frame.configuration.box[:d], [side] * d, rtol=1e-7)
            assert frame.log["coldblast/time"][0] == t
            assert bytes(frame.log["coldblast/run_id"]).decode() == run.summary["run_id"]
            # the snapshot's own subset, particle for particle (snapshot_<t>.csv holds the same ids)
            ids = frame.log["particles/id"]
            np.testing.assert_array_equal(ids, csv[t].id)
            assert p.N == len(ids) == len(csv[t])
            assert p.types == ["host", "impurity"]
            impurity = p.typeid == 1
            np.testing.assert_array_equal(impurity, csv[t].impurity)
            assert np.count_nonzero(impurity) == 3
            assert (p.mass[impurity] == np.float32(mass)).all() and (p.mass[~impurity] == 1.0).all()
            assert (p.diameter[~impurity] == np.float32(2 * run.summary["a"])).all()
            velocity = frame.log["particles/velocity_float64"]
            np.testing.assert_allclose(p.velocity, velocity, rtol=1e-6, atol=1e-30)
            masses = np.where(impurity, mass, 1.0)
            # the default subset holds every moving particle, so all of E
            assert 0.5 * np.sum(masses * np.sum(velocity**2, axis=1)) == pytest.approx(E, rel=1e-12)
            if d == 2:
                assert not p.position[:, 2].any() and frame.configuration.box[2] == 0
            np.testing.assert_allclose(p.position[:, :d], csv[t].position, rtol=1e-6, atol=1e-4)


def test_gsd_command_line(tmp_path):
    blast(tmp_path, 2, 5.0, 1.0, stride=2)
    env = dict(os.environ)
    command = [sys.executable, "-m", "coldblast", "gsd"]
    done = subprocess.run(command + [str(tmp_path / "run"), "-o", str(tmp_path / "blast.gsd")], capture_output=True,
                          text=True, env=env, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"wrote {tmp_path / 'blast.gsd'}"
    with gsd_hoomd.open(str(tmp_path / "blast.gsd"), mode="rb") as trajectory:
        assert len(trajectory) == 3
        assert (np.diff(trajectory[0].log["particles/id"]) > 0).all()
    assert not [f for f in os.listdir(tmp_path) if f.endswith(".tmp")]  # no temporary left
    # bad input: exit 2 naming the argument; a device is left as it was
    for args, message in [([str(tmp_path / "nowhere")], "RUN_DIR = "),
                          ([str(tmp_path / "run"), "--realization", "4"], "holds no snapshots_realization_4.extxyz"),
                          ([str(tmp_path / "run"), "--realization", "-1"], "--realization = -1"),
                          ([str(tmp_path / "run"), "-o", "/dev/null"], "-o = /dev/null is not a regular file"),
                          ([str(tmp_path / "run"), "-o", str(tmp_path / "no" / "x.gsd")], "does not exist")]:
        done = subprocess.run(command + args, capture_output=True, text=True, env=env)
        assert done.returncode == 2 and message in done.stderr, (args, done.stderr)
    assert os.path.exists("/dev/null") and not os.path.isfile("/dev/null")
    done = subprocess.run([sys.executable, "-m", "coldblast"], capture_output=True, text=True, env=env)
    assert done.returncode == 2 and "gsd" in done.stderr
