#!/usr/bin/env bash
# Peer benchmark against Pinocchio from pip's `pin` wheel (by hand, not run in CI).
#
#   bash bench/pinocchio/run.sh            # 200000 calls per round
#   CALLS=20000 bash bench/pinocchio/run.sh
#   ARMS=prismatic VARIANTS=hdr-generic bash bench/pinocchio/run.sh
#   ARMS=spatial VARIANTS=hdr-native bash bench/pinocchio/run.sh
#   ARMS=spatial-dynamics VARIANTS=hdr-native REPS=7 bash bench/pinocchio/run.sh
#
# Environment:
#   WORK        work dir (default /tmp/pinocchio_bench): venv, binaries, outputs
#   PIN_VERSION pin wheel version (default 4.1.0)
#   CALLS       calls per timing round (default 200000; 21 rounds, median reported)
#   VARIANTS    subset of "hdr-native hdr-generic lib" (default: all three)
#   CXX         compiler (default g++)
#   BUILD       1 (default) builds the variants; 0 reuses the binaries already in WORK
#   ARMS        "random" (default: the RandomN arms of benches/dynamics.rs, six ops) or
#               "prismatic" (the arms of benches/support/prismatic_arms.rs, rnea/crba/aba;
#               before timing, Pinocchio's results at four states are compared with the
#               generated code's from `cargo bench --bench prismatic -- --values`, which
#               this script runs in the repository, with the caller's CARGO_TARGET_DIR) or
#               "spatial" (the PUMA 560, UR5 and Franka Panda of benches/spatial.rs:
#               Pinocchio's computeFrameJacobian in LOCAL_WORLD_ALIGNED against the generated
#               tip_pose + jacobian; checked first as for "prismatic", with
#               `cargo bench --bench spatial -- --values`; then REPS turns, each timing the
#               generated code (`cargo bench --bench spatial -- --peer CALLS`, the same protocol
#               as peers.cpp) and then each Pinocchio build, the ratio of each pair taken within
#               its turn and the median of the REPS ratios reported) or
#               "spatial-dynamics" (the PUMA 560, UR5 and Franka Panda of
#               benches/spatial_dynamics.rs with their mass properties: the generated
#               inverse_dynamics, mass_matrix, forward_dynamics and mass_matrix_and_bias against
#               rnea, crba, aba and crba + nonLinearEffects, crba and aba in both conventions,
#               forward_dynamics also against crba + nonLinearEffects + cholesky::decompose +
#               cholesky::solve; inverse_dynamics_derivatives and
#               forward_dynamics_derivatives against computeRNEADerivatives and
#               computeABADerivatives (Minv symmetrised); Identification's regressor and
#               base_regressor against computeJointTorqueRegressor (the issue's target: the
#               base regressor at least 10x faster); checked first with
#               `cargo bench --bench spatial_dynamics -- --values` (every one of those results
#               against the generated code's; the regressor's rigid-body columns against
#               Pinocchio's, the PUMA's after changing its parameters from the DH frames the
#               derive uses to Pinocchio's joint frames, see peers.cpp; Pinocchio's own, in the
#               joint frames, shown but not checked), then timed in turns as "spatial")
#   REPS        ARMS=spatial and spatial-dynamics: how many times the programs take turns
#               (default 5)
#
# Builds (all -O3 -DNDEBUG -std=c++17 plus the compile definitions that the wheel's
# pinocchio::pinocchio_headers CMake target exports):
#   hdr-native  header-only, -march=native: every algorithm instantiated and optimised in
#               peers.cpp for this CPU;
#   hdr-generic header-only, no -march (x86-64 baseline), to see what -march=native buys;
#   lib         -DPINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION, linked to the wheel's
#               libpinocchio_default.so: all six ops run the wheel's precompiled instances
#               (as a CMake project using pinocchio::pinocchio does).
#               No -march here: the wheel is built for the x86-64 baseline and Eigen's
#               alignment (so the layout of pinocchio::Data) must match it.
# Each header-only build takes about 6 minutes here; the three build in parallel.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
WORK="${WORK:-/tmp/pinocchio_bench}"
PIN_VERSION="${PIN_VERSION:-4.1.0}"
CALLS="${CALLS:-200000}"
VARIANTS="${VARIANTS:-hdr-native hdr-generic lib}"
CXX="${CXX:-g++}"
ARMS="${ARMS:-random}"
case "$ARMS" in
  random) OUT=out ;;
  prismatic) OUT=out_prismatic ;;
  spatial) OUT=out_spatial ;;
  spatial-dynamics) OUT=out_spatial_dynamics ;;
  *) echo "ARMS is random, prismatic, spatial or spatial-dynamics, not $ARMS" >&2; exit 1 ;;
esac
# The cargo bench that serves each mode.
BENCH="${ARMS//-/_}"
mkdir -p "$WORK"

# 1. pin (+ its cmeel dependencies: boost, urdfdom, coal, ...) and Eigen's headers.
if [ ! -x "$WORK/venv/bin/python" ]; then
  python3 -m venv "$WORK/venv"
fi
PY="$WORK/venv/bin/python"
"$PY" -m pip install -q "pin==$PIN_VERSION" cmeel-eigen

# 2. The wheel's prefix (include/, lib/) from cmeel itself.
PREFIX="$("$PY" -m cmeel cmake 2>/dev/null | tr ':' '\n' | head -n1)"
[ -f "$PREFIX/include/pinocchio/config.hpp" ] || { echo "no pinocchio headers under $PREFIX" >&2; exit 1; }
[ -f "$PREFIX/include/eigen3/Eigen/Core" ] || { echo "no Eigen headers under $PREFIX" >&2; exit 1; }
echo "# prefix: $PREFIX"
echo "# pin $("$PY" -c 'import pinocchio; print(pinocchio.__version__)'), $("$CXX" --version | head -n1)"
echo "# cpu: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2-)"

# From lib/cmake/pinocchio/pinocchioTargets.cmake (pinocchio_headers): the JointModel variant
# is sized with these, so they must match the wheel's library.
DEFS="-DBOOST_MPL_LIMIT_LIST_SIZE=30 -DBOOST_MPL_LIMIT_VECTOR_SIZE=30 \
-DBOOST_MPL_CFG_NO_PREPROCESSED_HEADERS -DBOOST_FUSION_INVOKE_MAX_ARITY=12"
BASE="-O3 -DNDEBUG -std=c++17 $DEFS -I$PREFIX/include -I$PREFIX/include/eigen3"
# GCC 12 warns (-Wstringop-overread) inside Eigen's AVX-512 code; harmless, and noisy.
QUIET="-Wno-stringop-overread -Wno-array-bounds"

flags_of() {
  case "$1" in
    hdr-native) echo "$BASE -march=native" ;;
    hdr-generic) echo "$BASE" ;;
    lib) echo "$BASE -DPINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION" ;;
    *) echo "unknown variant $1" >&2; exit 1 ;;
  esac
}
libs_of() {
  case "$1" in
    lib) echo "-L$PREFIX/lib -Wl,-rpath,$PREFIX/lib -lpinocchio_default" ;;
    *) echo "" ;;
  esac
}

# 3. Build (in parallel), then run one after the other.
pids=()
if [ "${BUILD:-1}" = 1 ]; then BUILT="$VARIANTS"; else BUILT=""; fi
for v in $BUILT; do
  echo "# build $v: $CXX $(flags_of "$v" | sed "s#$PREFIX#\$PREFIX#g") $(libs_of "$v" | sed "s#$PREFIX#\$PREFIX#g")"
  # shellcheck disable=SC2046
  "$CXX" $(flags_of "$v") $QUIET -DVARIANT="\"$v\"" "$HERE/peers.cpp" -o "$WORK/peers_$v" \
    $(libs_of "$v") >"$WORK/build_$v.log" 2>&1 &
  pids+=("$!")
done
status=0
for p in "${pids[@]}"; do wait "$p" || status=1; done
for v in $VARIANTS; do [ -x "$WORK/peers_$v" ] || status=1; done
if [ "$status" != 0 ]; then
  for v in $VARIANTS; do [ -x "$WORK/peers_$v" ] || { echo "build $v failed:" >&2; tail -n 30 "$WORK/build_$v.log" >&2; }; done
  exit 1
fi

# The prismatic arms: Pinocchio's rnea, crba and aba against the generated code at the same
# states (one call per round, so only the checks take time), to 1e-9 relative. The spatial
# arms: Pinocchio's tool pose (oMf) and frame Jacobian against tip_pose and jacobian. The
# spatial dynamics: rnea, crba, nonLinearEffects, crba + nonLinearEffects and aba (crba and aba
# in both conventions, `_world` compared with the same generated result) against the generated
# inverse_dynamics, mass_matrix, bias, mass_matrix_and_bias and forward_dynamics, and
# computeRNEADerivatives and computeABADerivatives against inverse_dynamics_derivatives and
# forward_dynamics_derivatives, computeJointTorqueRegressor (in the arm's link frames) against
# the rigid-body columns of regressor; for the PUMA also computeJointTorqueRegressor as it
# comes (the parameters in Pinocchio's joint frames, not the DH frames), shown, not checked.
if [ "$ARMS" != random ]; then
  (cd "$HERE/../.." && cargo bench -q --bench "$BENCH" -- --values) >"$WORK/values_rust.txt"
  grep -v '^# value' "$WORK/values_rust.txt" || true
  for v in $VARIANTS; do
    "$WORK/peers_$v" 1 "$ARMS" >"$WORK/values_$v.txt"
    grep '^# .*|' "$WORK/values_$v.txt" || true
    "$PY" - "$WORK/values_rust.txt" "$WORK/values_$v.txt" "$v" <<'EOF'
import sys
def values(path):
    out = {}
    for line in open(path):
        if line.startswith("# value,"):
            _, arm, op, k, nums = [x.strip() for x in line.split(",")]
            out[(arm, op, int(k))] = [float(x) for x in nums.split()]
    return out
rust, pin, variant = values(sys.argv[1]), values(sys.argv[2]), sys.argv[3]
# Pinocchio's `_world` results (spatial-dynamics) are checked against the same generated ones,
# and its accelerations by crba + nonLinearEffects + Cholesky against forward_dynamics too.
# Its regressor in the joint frames (the PUMA's) differs from the generated one, whose
# parameters are in the DH frames: shown, not checked.
alias = {"crba+nle+cholesky": "aba", "regressor_joint_frames": "regressor"}
unchecked = {"regressor_joint_frames"}
same = lambda key: (key[0], alias.get(key[1], key[1].replace("_world", "")), key[2])
assert rust and set(rust) == {same(key) for key in pin}, "the two programs print different results"
worst = {}
for key, b in pin.items():
    a = rust[same(key)]
    assert len(a) == len(b), f"{key}: {len(a)} numbers against {len(b)}"
    scale = max(max(map(abs, a)), max(map(abs, b)), 1.0)
    err = max(abs(x - y) for x, y in zip(a, b)) / scale
    worst[key[:2]] = max(worst.get(key[:2], 0.0), err)
print(f"# agreement ({variant}), generated vs Pinocchio, largest relative difference over 4 states:")
for (arm, op), err in worst.items():
    note = " (not checked: other frames)" if op in unchecked else ""
    print(f"#   {arm:13s} {op:22s} {err:.1e}{note}")
if max(err for (arm, op), err in worst.items() if op not in unchecked) > 1e-9:
    sys.exit("generated and Pinocchio disagree")
EOF
  done
fi

# The spatial arms: the generated code and Pinocchio take turns, REPS times; each ratio is
# taken within one turn (the load drifts less within a turn than across the run).
if [ "$ARMS" = spatial ] || [ "$ARMS" = spatial-dynamics ]; then
  REPS="${REPS:-5}"
  for r in $(seq 1 "$REPS"); do
    echo "# turn $r: generated (load: $(cut -d' ' -f1-3 /proc/loadavg))"
    (cd "$HERE/../.." && cargo bench -q --bench "$BENCH" -- --peer "$CALLS") \
      | tee "$WORK/${OUT}_rust_$r.txt"
    for v in $VARIANTS; do
      echo "# turn $r: $v (load: $(cut -d' ' -f1-3 /proc/loadavg))"
      "$WORK/peers_$v" "$CALLS" "$ARMS" | grep -v '^# value' | tee "$WORK/${OUT}_${v}_$r.txt"
    done
  done
fi
if [ "$ARMS" = spatial ]; then
  "$PY" - "$WORK" "$OUT" "$REPS" $VARIANTS <<'EOF'
import statistics, sys
work, out, reps, variants = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
def rows(path):
    got = {}
    for line in open(path):
        if line.startswith("#") or line.startswith("variant"):
            continue
        _, n, op, wall, cpu = [x.strip() for x in line.split(",")]
        got[op.split("/")[0]] = (int(n), float(cpu), float(wall))
    return got
rust = [rows(f"{work}/{out}_rust_{r}.txt") for r in range(1, reps + 1)]
pin = {v: [rows(f"{work}/{out}_{v}_{r}.txt") for r in range(1, reps + 1)] for v in variants}
for idx, what in ((1, "thread CPU time"), (2, "wall clock")):
    print(f"\nmedian ns/call over {reps} turns, {what}; Pinocchio / generated: the median of "
          f"the turns' ratios (smallest-largest)\n")
    head = "| arm | N | generated tip_pose + jacobian |"
    for v in variants:
        head += f" Pinocchio {v} computeFrameJacobian | Pinocchio / generated |"
    print(head)
    print("|---|---|---:|" + "---:|---:|" * len(variants))
    for arm, (n, _, _) in rust[0].items():
        line = f"| {arm} | {n} | {statistics.median(t[arm][idx] for t in rust):.1f} |"
        for v in variants:
            ratios = [p[arm][idx] / t[arm][idx] for p, t in zip(pin[v], rust)]
            line += (f" {statistics.median(p[arm][idx] for p in pin[v]):.1f} |"
                     f" {statistics.median(ratios):.2f}x ({min(ratios):.2f}-{max(ratios):.2f}) |")
        print(line)
EOF
  exit 0
fi
if [ "$ARMS" = spatial-dynamics ]; then
  "$PY" - "$WORK" "$OUT" "$REPS" $VARIANTS <<'EOF'
import statistics, sys
work, out, reps, variants = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
def rows(path):
    got = {}
    for line in open(path):
        if line.startswith("#") or line.startswith("variant"):
            continue
        _, n, op, wall, cpu = [x.strip() for x in line.split(",")]
        arm, op = op.split("/")
        got[(arm, op)] = (int(n), float(cpu), float(wall))
    return got
rust = [rows(f"{work}/{out}_rust_{r}.txt") for r in range(1, reps + 1)]
pin = {v: [rows(f"{work}/{out}_{v}_{r}.txt") for r in range(1, reps + 1)] for v in variants}
# Each generated method against each Pinocchio call that gives the same quantities.
pairs = [
    ("inverse_dynamics", "rnea"),
    ("mass_matrix", "crba"),
    ("mass_matrix", "crba_world"),
    ("forward_dynamics", "aba"),
    ("forward_dynamics", "aba_world"),
    ("forward_dynamics", "crba+nle+cholesky"),
    ("mass_matrix_and_bias", "crba+nle"),
    ("mass_matrix_and_bias", "crba_world+nle"),
    ("inverse_dynamics_derivatives", "rnea_derivatives"),
    ("forward_dynamics_derivatives", "aba_derivatives"),
    ("regressor", "regressor"),
    ("base_regressor", "regressor"),
]
# peers.cpp's short op names, spelled out where they would read as the generated method's.
shown = {"regressor": "computeJointTorqueRegressor"}
arms = list(dict.fromkeys(arm for arm, _ in rust[0]))
for idx, what in ((1, "thread CPU time"), (2, "wall clock")):
    print(f"\nmedian ns/call over {reps} turns, {what}; Pinocchio / generated: the median of "
          f"the turns' ratios (smallest-largest)\n")
    head = "| arm | N | generated | ns | Pinocchio |"
    for v in variants:
        head += f" {v} ns | Pinocchio / generated |"
    print(head)
    print("|---|---|---|---:|---|" + "---:|---:|" * len(variants))
    for arm in arms:
        for ours, theirs in pairs:
            n = rust[0][(arm, ours)][0]
            line = (f"| {arm} | {n} | {ours} | "
                    f"{statistics.median(t[(arm, ours)][idx] for t in rust):.1f} | "
                    f"{shown.get(theirs, theirs)} |")
            for v in variants:
                ratios = [p[(arm, theirs)][idx] / t[(arm, ours)][idx] for p, t in zip(pin[v], rust)]
                line += (f" {statistics.median(p[(arm, theirs)][idx] for p in pin[v]):.1f} |"
                         f" {statistics.median(ratios):.2f}x ({min(ratios):.2f}-{max(ratios):.2f}) |")
            print(line)
# The issue's target: base_regressor at least 10x faster than computeJointTorqueRegressor.
print("\nregressors, computeJointTorqueRegressor / generated by thread CPU time (median of the "
      "turns' ratios; target: base_regressor >= 10x)")
for v in variants:
    for arm in arms:
        got = {}
        for ours in ("regressor", "base_regressor"):
            got[ours] = statistics.median(
                p[(arm, "regressor")][1] / t[(arm, ours)][1] for p, t in zip(pin[v], rust))
        print(f"  {v} {arm}: regressor vs computeJointTorqueRegressor {got['regressor']:.2f}x, "
              f"base_regressor vs computeJointTorqueRegressor {got['base_regressor']:.2f}x "
              f"({'met' if got['base_regressor'] >= 10 else 'NOT met'})")
EOF
  exit 0
fi

for v in $VARIANTS; do
  echo "# run $v (load: $(cut -d' ' -f1-3 /proc/loadavg))"
  "$WORK/peers_$v" "$CALLS" "$ARMS" | tee "$WORK/${OUT}_$v.txt"
done

# 4. Tables: N, op, ns/call per build, by thread CPU time (robust when the machine is shared)
#    and by the wall clock (std::chrono::steady_clock).
"$PY" - "$WORK" "$OUT" $VARIANTS <<'EOF'
import sys
work, out, variants = sys.argv[1], sys.argv[2], sys.argv[3:]
rows, order = {}, []
for v in variants:
    for line in open(f"{work}/{out}_{v}.txt"):
        if line.startswith("#") or line.startswith("variant"):
            continue
        _, n, op, wall, cpu = [x.strip() for x in line.split(",")]
        key = (int(n), op)
        if key not in rows:
            order.append(key)
        rows.setdefault(key, {})[v] = (float(cpu), float(wall))
for idx, what in ((0, "thread CPU time"), (1, "wall clock")):
    print(f"\nmedian ns/call, {what}\n")
    print("| N | op | " + " | ".join(variants) + " |")
    print("|---|---|" + "---:|" * len(variants))
    for key in order:
        print(f"| {key[0]} | {key[1]} | " + " | ".join(
            f"{rows[key][v][idx]:.0f}" if v in rows[key] else "-" for v in variants) + " |")
EOF
