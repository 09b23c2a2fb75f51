"""MuJoCo's dynamics of tests/data/springs.xml (or the model named on the command line), a
test arm for joint springs, for tests/models_peers.rs. Run by hand (CI installs no MuJoCo):

    python3 bench/models/springs.py > tests/data/springs_peers.txt
    python3 bench/models/springs.py tests/data/planar_springs.xml \
        > tests/data/planar_springs_peers.txt

The second joint of each model is its slide, sampled in [-0.1, 0.2).

Written with Python 3.11.7, mujoco 4.0.1, numpy 2.4.6. Constraints and contacts are off, so
that qfrc_passive holds the springs and the damping alone.
"""

import platform
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fixtures import check_spd, line, rigid_bodies_only  # noqa: E402  (shared with the models' fixture)

ROOT = Path(__file__).resolve().parents[2]


def main():
    model = sys.argv[1] if len(sys.argv) > 1 else "tests/data/springs.xml"
    m = mujoco.MjModel.from_xml_path(str(ROOT / model))
    rigid_bodies_only(m)
    d = mujoco.MjData(m)
    rng = np.random.default_rng(20261205)
    names = [mujoco.mj_id2name(m, mujoco.mjtObj.mjOBJ_JOINT, j) for j in range(m.njnt)]
    out = [
        f"# {model}, written by bench/models/springs.py with Python {platform.python_version()}, "
        f"mujoco {mujoco.__version__}, numpy {np.__version__}.",
        "# Per state: q qd qdd; M (mj_fullM, row-major); bias (qfrc_bias: Coriolis, centrifugal,",
        "# gravity); passive (qfrc_passive: -stiffness (q - springref) - damping qd); tau",
        "# (qfrc_inverse of mj_inverse: M qdd + bias - passive).",
        f"# jnt_stiffness {[float(x) for x in m.jnt_stiffness]}, qpos_spring {[float(x) for x in m.qpos_spring]},",
        f"# qpos0 {[float(x) for x in m.qpos0]}, dof_damping {[float(x) for x in m.dof_damping]}.",
        "joints " + " ".join(names),
    ]
    worst = 0.0
    for _ in range(3):
        q = rng.uniform(-1.0, 1.0, m.nq)
        q[1] = rng.uniform(-0.1, 0.2)
        qd = rng.uniform(-1.0, 1.0, m.nv)
        qdd = rng.uniform(-1.0, 1.0, m.nv)
        d.qpos[:], d.qvel[:], d.qacc[:] = q, qd, qdd
        mujoco.mj_forward(m, d)
        M = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, d, M)
        check_spd("springs", M)
        d.qacc[:] = qdd
        mujoco.mj_inverse(m, d)
        tau = d.qfrc_inverse.copy()
        worst = max(worst, float(np.max(np.abs(M @ qdd + d.qfrc_bias - d.qfrc_passive - tau))))
        for key, v in [("q", q), ("qd", qd), ("qdd", qdd), ("M", M), ("bias", d.qfrc_bias),
                       ("passive", d.qfrc_passive), ("tau", tau)]:
            out.append(line(key, v))
    if worst > 1e-10:
        raise SystemExit(f"mj_inverse disagrees with M qdd + bias - passive by {worst}")
    sys.stderr.write(f"mj_inverse against M qdd + bias - passive: {worst:.1e}\n")
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
