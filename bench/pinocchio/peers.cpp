// Peer benchmark: Pinocchio (pip wheel `pin`) on the planar arms of benches/dynamics.rs,
// with the argument `prismatic` on the mixed arms of benches/prismatic.rs, and with `spatial`
// on the spatial arms of benches/spatial.rs (the tool pose and its Jacobian).
//
// Not run in CI. Build and run with bench/pinocchio/run.sh, which compiles this file three times:
//   - "hdr-native" / "hdr-generic": header-only, every Pinocchio template instantiated in this
//            file with our flags (with / without -march=native);
//   - "lib": -DPINOCCHIO_ENABLE_TEMPLATE_INSTANTIATION, so all six ops call the instances
//            precompiled in the wheel's libpinocchio_default.so (the way a CMake project
//            linking pinocchio::pinocchio uses it; check with nm -DC --undefined-only).
// VARIANT (a string) names the build in the output.
//
// Per call timed: computeJointTorqueRegressor, rnea, crba, aba, computeRNEADerivatives,
// computeABADerivatives, each over 64 fixed pseudo-random states (q, v, a in [-1, 1]; aba and
// its derivatives take a as tau) cycled through; CALLS calls per round (default 200000,
// argv[1] overrides), ROUNDS = 21 rounds after one warm-up round; reported: the median ns/call
// of the rounds by the wall clock (std::chrono::steady_clock) and by the thread's CPU time.
//
// argv[2] picks the arms: `random` (the default: the RandomN arms, all six ops) or `prismatic`
// (benches/support/prismatic_arms.rs: MixedN with prismatic joints and their all-revolute twins
// AllRevoluteN; rnea, crba and aba, after printing their results at the first four states as
// `# value, ARM, OP, K, ...` lines for run.sh to compare with the generated code's) or
// `spatial` (the PUMA 560, UR5 and Franka Panda of benches/spatial.rs, built from their DH
// parameters; one op, computeFrameJacobian of the tool frame in LOCAL_WORLD_ALIGNED, which also
// places the frame, over 64 states with angles in [-pi, pi); its tool pose and Jacobian at the
// first four states printed first as `# value` lines, as for `prismatic`) or
// `spatial-dynamics` (the PUMA 560, UR5 and Franka Panda of benches/spatial_dynamics.rs with
// their mass properties: rnea, crba, aba and crba + nonLinearEffects, crba and aba in both
// conventions, crba + nonLinearEffects + Pinocchio's Cholesky solve for the accelerations,
// computeRNEADerivatives, computeABADerivatives and computeJointTorqueRegressor; their results
// at the first four states printed first).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <time.h>

#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/regressor.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/frames.hpp>
#include <pinocchio/algorithm/cholesky.hpp>

#ifndef VARIANT
#define VARIANT "unnamed"
#endif

namespace pin = pinocchio;

static constexpr double GRAVITY = 9.80665;
static constexpr int NSTATES = 64;
static constexpr int ROUNDS = 21;

// One link as in the #[arm(...)] attributes of the benches: length, mass, inertia about the
// COM, COM along the link (x of the link frame), COM across it (y), and the joint's kind:
// 'R' revolute about z, 'P' prismatic along the previous link's x.
struct Link
{
  double length, mass, inertia, com;
  double com_y = 0.;
  char joint = 'R';
};

struct Arm
{
  const char * name;
  std::vector<Link> links;
};

// Exactly the RandomN structs of benches/dynamics.rs (fractions written as there).
static std::vector<Arm> arms()
{
  return {
    {"Random2",
     {
       {6. / 1, 3. / 1, 6. / 25, 12. / 5},
       {4. / 1, 38. / 5, 1. / 25, 4. / 1},
     }},
    {"Random3",
     {
       {12. / 5, 26. / 5, 5. / 4, 6. / 25},
       {23. / 10, 2. / 1, 1. / 20, 69. / 100},
       {2. / 1, 3. / 2, 11. / 25, 3. / 5},
     }},
    {"Random4",
     {
       {9. / 5, 13. / 4, 1. / 40, 9. / 5},
       {9. / 5, 9. / 2, 11. / 40, -27. / 50},
       {23. / 8, 3. / 4, 3. / 10, 69. / 20},
       {14. / 5, 16. / 5, 23. / 25, -14. / 25},
     }},
    {"Random6",
     {
       {3. / 1, 12. / 5, 1. / 50, 12. / 5},
       {4. / 1, 15. / 2, 23. / 25, 6. / 5},
       {7. / 5, 31. / 8, 17. / 40, 7. / 10},
       {9. / 2, 39. / 8, 7. / 10, -9. / 10},
       {17. / 4, 15. / 8, 17. / 40, 17. / 40},
       {7. / 4, 9. / 1, 1. / 4, 21. / 20},
     }},
    {"Random8",
     {
       {9. / 4, 11. / 8, 16. / 25, -9. / 20},
       {3. / 5, 4. / 5, 3. / 5, 3. / 10},
       {9. / 5, 11. / 4, 3. / 2, 54. / 25},
       {14. / 5, 2. / 1, 21. / 50, 0. / 1},
       {9. / 10, 5. / 1, 1. / 25, 27. / 50},
       {4. / 5, 6. / 5, 2. / 5, 24. / 25},
       {3. / 2, 16. / 5, 29. / 25, 0. / 1},
       {16. / 5, 33. / 8, 3. / 10, 96. / 25},
     }},
  };
}

// The arms of benches/support/prismatic_arms.rs, in the same order as printed there: each
// MixedN (joints RP, PRR, RPRP, RPRPRP, RPRPRPRP) next to AllRevoluteN, the same links with
// every joint revolute. Fractions written as in the Rust attributes.
static std::vector<Arm> prismatic_arms()
{
  struct Spec
  {
    const char * mixed;
    const char * revolute;
    const char * joints;
    std::vector<Link> links;
  };
  const std::vector<Spec> specs = {
    {"Mixed2", "AllRevolute2", "RP",
     {
       {6. / 1, 3. / 1, 6. / 25, 12. / 5, 3. / 10},
       {4. / 1, 38. / 5, 1. / 25, 4. / 1, -1. / 5},
     }},
    {"Mixed3", "AllRevolute3", "PRR",
     {
       {12. / 5, 26. / 5, 5. / 4, 6. / 25, 1. / 10},
       {23. / 10, 2. / 1, 1. / 20, 69. / 100, -3. / 20},
       {2. / 1, 3. / 2, 11. / 25, 3. / 5, 1. / 5},
     }},
    {"Mixed4", "AllRevolute4", "RPRP",
     {
       {9. / 5, 13. / 4, 1. / 40, 9. / 5, 1. / 10},
       {9. / 5, 9. / 2, 11. / 40, -27. / 50, 1. / 5},
       {23. / 8, 3. / 4, 3. / 10, 69. / 20, -1. / 4},
       {14. / 5, 16. / 5, 23. / 25, -14. / 25, 3. / 10},
     }},
    {"Mixed6", "AllRevolute6", "RPRPRP",
     {
       {3. / 1, 12. / 5, 1. / 50, 12. / 5, 1. / 5},
       {4. / 1, 15. / 2, 23. / 25, 6. / 5, -1. / 10},
       {7. / 5, 31. / 8, 17. / 40, 7. / 10, 3. / 20},
       {9. / 2, 39. / 8, 7. / 10, -9. / 10, 1. / 4},
       {17. / 4, 15. / 8, 17. / 40, 17. / 40, -1. / 5},
       {7. / 4, 9. / 1, 1. / 4, 21. / 20, 1. / 10},
     }},
    {"Mixed8", "AllRevolute8", "RPRPRPRP",
     {
       {9. / 4, 11. / 8, 16. / 25, -9. / 20, 1. / 10},
       {3. / 5, 4. / 5, 3. / 5, 3. / 10, -1. / 5},
       {9. / 5, 11. / 4, 3. / 2, 54. / 25, 1. / 4},
       {14. / 5, 2. / 1, 21. / 50, 0. / 1, 3. / 20},
       {9. / 10, 5. / 1, 1. / 25, 27. / 50, -1. / 10},
       {4. / 5, 6. / 5, 2. / 5, 24. / 25, 1. / 5},
       {3. / 2, 16. / 5, 29. / 25, 0. / 1, -3. / 20},
       {16. / 5, 33. / 8, 3. / 10, 96. / 25, 1. / 10},
     }},
  };
  std::vector<Arm> out;
  for (const Spec & s : specs)
  {
    Arm mixed{s.mixed, s.links}, revolute{s.revolute, s.links};
    for (std::size_t i = 0; i < s.links.size(); ++i)
      mixed.links[i].joint = s.joints[i];
    out.push_back(mixed);
    out.push_back(revolute);
  }
  return out;
}

// Planar serial chain: joint i revolute about z (JointModelRZ) or prismatic along x
// (JointModelPX: it slides link i along the previous link's x without turning it, the crate's
// prismatic joint), placed at (l_{i-1}, 0, 0) in the previous link's frame (the first at the
// origin); link i's COM at (c_i, c_y_i, 0) with rotational inertia diag(Izz, Izz, Izz) about
// the COM (Ixx = Iyy = Izz as in the URDF of the dynibo bench: any positive values do, planar
// motion sees Izz alone). Gravity along -y.
static pin::Model build(const Arm & arm)
{
  pin::Model model;
  model.gravity.linear(Eigen::Vector3d(0., -GRAVITY, 0.));
  pin::JointIndex parent = 0;
  double offset = 0.;
  int k = 0;
  for (const Link & l : arm.links)
  {
    ++k;
    pin::SE3 placement(Eigen::Matrix3d::Identity(), Eigen::Vector3d(offset, 0., 0.));
    const std::string name = "joint" + std::to_string(k);
    pin::JointIndex j = l.joint == 'P'
                          ? model.addJoint(parent, pin::JointModelPX(), placement, name)
                          : model.addJoint(parent, pin::JointModelRZ(), placement, name);
    const double i3 = std::max(l.inertia, 1e-9);
    // Symmetric3(xx, xy, yy, xz, yz, zz), about the COM.
    pin::Inertia body(
      l.mass, Eigen::Vector3d(l.com, l.com_y, 0.), pin::Symmetric3(i3, 0., i3, 0., 0., l.inertia));
    model.appendBodyToJoint(j, body, pin::SE3::Identity());
    parent = j;
    offset = l.length;
  }
  return model;
}

// The xorshift of benches/dynamics.rs `state`: deterministic vector in [-range, range].
static Eigen::VectorXd state(int n, std::uint64_t seed, double range)
{
  std::uint64_t s = seed * 0x9E3779B97F4A7C15ull + 1;
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i)
  {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    const double u = double(s >> 11) / double(std::uint64_t(1) << 53);
    x[i] = (2. * u - 1.) * range;
  }
  return x;
}

struct States
{
  std::vector<Eigen::VectorXd> q, v, a;
};

static States states(int n)
{
  States st;
  for (int k = 0; k < NSTATES; ++k)
  {
    st.q.push_back(state(n, 1000 + 3 * k, 1.));
    st.v.push_back(state(n, 1001 + 3 * k, 1.));
    st.a.push_back(state(n, 1002 + 3 * k, 1.));
  }
  return st;
}

// The precompiled instances of crba and aba in the wheel's library (lib build) take their
// vectors as Eigen::Ref<const VectorXd> (rnea and the derivatives convert to Ref themselves;
// computeJointTorqueRegressor's instance takes VectorXd). Wrapping costs nothing.
using Ref = Eigen::Ref<const Eigen::VectorXd>;

static double checksum = 0.;

static double thread_cpu_ns()
{
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e9 + double(ts.tv_nsec);
}

struct Timing
{
  double wall, cpu; // median ns/call over the rounds: std::chrono::steady_clock, thread CPU time
};

static double median(std::vector<double> x)
{
  std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
  return x[x.size() / 2];
}

// ROUNDS rounds of `calls` calls (after one warm-up round), timed by the wall clock
// (std::chrono::steady_clock) and by this thread's CPU time; the medians per call.
// The CPU time leaves out the time the thread was descheduled, so it is the robust number on a
// loaded machine. `f(k)` runs the op on state k and returns one entry of its output (summed
// into a checksum that is printed, so that no call can be optimised away).
template<typename F>
static Timing time_op(F && f, long calls)
{
  std::vector<double> wall, cpu;
  for (int r = -1; r < ROUNDS; ++r)
  {
    double acc = 0.;
    int k = 0;
    const double c0 = thread_cpu_ns();
    const auto t0 = std::chrono::steady_clock::now();
    for (long i = 0; i < calls; ++i)
    {
      acc += f(k);
      if (++k == NSTATES)
        k = 0;
    }
    const auto t1 = std::chrono::steady_clock::now();
    const double c1 = thread_cpu_ns();
    checksum += acc;
    if (r >= 0)
    {
      wall.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / double(calls));
      cpu.push_back((c1 - c0) / double(calls));
    }
  }
  return {median(wall), median(cpu)};
}

// Closed-form inverse dynamics of a two-link planar arm (angles from +x, gravity along -y),
// independent of Pinocchio, to check the model built above.
static Eigen::Vector2d two_link_tau(
  const Arm & arm, const Eigen::Vector2d & q, const Eigen::Vector2d & v, const Eigen::Vector2d & a)
{
  const Link &L1 = arm.links[0], &L2 = arm.links[1];
  const double m1 = L1.mass, c1 = L1.com, I1 = L1.inertia, l1 = L1.length;
  const double m2 = L2.mass, c2 = L2.com, I2 = L2.inertia;
  const double c = std::cos(q[1]), s = std::sin(q[1]);
  const double M11 = I1 + m1 * c1 * c1 + I2 + m2 * (l1 * l1 + c2 * c2 + 2 * l1 * c2 * c);
  const double M12 = I2 + m2 * (c2 * c2 + l1 * c2 * c);
  const double M22 = I2 + m2 * c2 * c2;
  const double h = -m2 * l1 * c2 * s;
  const double g2 = m2 * c2 * GRAVITY * std::cos(q[0] + q[1]);
  const double g1 = (m1 * c1 + m2 * l1) * GRAVITY * std::cos(q[0]) + g2;
  return Eigen::Vector2d(
    M11 * a[0] + M12 * a[1] + h * (2 * v[0] * v[1] + v[1] * v[1]) + g1,
    M12 * a[0] + M22 * a[1] - h * v[0] * v[0] + g2);
}

static void checks(const std::vector<Arm> & all)
{
  std::printf("# checks (%s)\n", VARIANT);
  const Arm & arm2 = all[0];
  pin::Model model = build(arm2);
  pin::Data data(model);

  const Eigen::Vector2d q(0.3, -0.8), v(1.0, 0.5), a(-2.0, 1.0);
  const Eigen::VectorXd tau = pin::rnea(model, data, q, v, a);
  const Eigen::Vector2d ref = two_link_tau(arm2, q, v, a);
  std::printf(
    "# N=2 rnea tau at q=(0.3,-0.8) v=(1.0,0.5) a=(-2.0,1.0): [%.17g, %.17g]\n", tau[0], tau[1]);
  std::printf(
    "# N=2 closed-form tau at that state:                  [%.17g, %.17g]  (max |diff| %.3g)\n",
    ref[0], ref[1], (tau - ref).cwiseAbs().maxCoeff());

  States st = states(2);
  const Eigen::VectorXd tau0 = pin::rnea(model, data, st.q[0], st.v[0], st.a[0]);
  const Eigen::Vector2d ref0 = two_link_tau(arm2, st.q[0], st.v[0], st.a[0]);
  std::printf(
    "# N=2 bench state 0: q=(%.17g, %.17g) v=(%.17g, %.17g) a=(%.17g, %.17g)\n", st.q[0][0],
    st.q[0][1], st.v[0][0], st.v[0][1], st.a[0][0], st.a[0][1]);
  std::printf(
    "# N=2 rnea tau at bench state 0: [%.17g, %.17g]  (closed form max |diff| %.3g)\n", tau0[0],
    tau0[1], (tau0 - ref0).cwiseAbs().maxCoeff());

  // Per arm: regressor * dynamic parameters == rnea, crba (upper triangle) * a + nle == rnea.
  for (const Arm & arm : all)
  {
    pin::Model m = build(arm);
    pin::Data d(m);
    const int n = int(arm.links.size());
    States s = states(n);
    Eigen::VectorXd pi(10 * n);
    for (int j = 0; j < n; ++j)
      pi.segment<10>(10 * j) = m.inertias[j + 1].toDynamicParameters();
    const Eigen::VectorXd t = pin::rnea(m, d, s.q[0], s.v[0], s.a[0]);
    const Eigen::MatrixXd Y = pin::computeJointTorqueRegressor(m, d, s.q[0], s.v[0], s.a[0]);
    Eigen::MatrixXd M = pin::crba(m, d, s.q[0]);
    M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
    const Eigen::VectorXd nle = pin::nonLinearEffects(m, d, s.q[0], s.v[0]);
    std::printf(
      "# N=%d regressor %ldx%ld, |Y pi - tau| = %.3g, |M a + nle - tau| = %.3g\n", n, Y.rows(),
      Y.cols(), (Y * pi - t).cwiseAbs().maxCoeff(), (M * s.a[0] + nle - t).cwiseAbs().maxCoeff());
  }
}

// Per arm: crba (upper triangle) * a + nle == rnea at the first state, and the results of rnea,
// crba (both triangles) and aba (a as tau) at the first four states, for run.sh to compare
// with the generated code's (`cargo bench --bench prismatic -- --values`).
static void prismatic_checks(const std::vector<Arm> & all)
{
  std::printf("# checks (%s)\n", VARIANT);
  for (const Arm & arm : all)
  {
    pin::Model m = build(arm);
    pin::Data d(m);
    const int n = int(arm.links.size());
    const States s = states(n);
    auto print = [&](const char * op, int k, const double * x, int len) {
      std::printf("# value, %s, %s, %d,", arm.name, op, k);
      for (int i = 0; i < len; ++i)
        std::printf(" %.17g", x[i]);
      std::printf("\n");
    };
    for (int k = 0; k < 4; ++k)
    {
      const Eigen::VectorXd t = pin::rnea(m, d, s.q[k], s.v[k], s.a[k]);
      Eigen::MatrixXd M = pin::crba(m, d, Ref(s.q[k]));
      M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
      const Eigen::VectorXd nle = pin::nonLinearEffects(m, d, s.q[k], s.v[k]);
      const Eigen::VectorXd ddq = pin::aba(m, d, Ref(s.q[k]), Ref(s.v[k]), Ref(s.a[k]));
      if (k == 0)
        std::printf(
          "# %s (N=%d): |M a + nle - tau| = %.3g\n", arm.name, n,
          (M * s.a[k] + nle - t).cwiseAbs().maxCoeff());
      print("rnea", k, t.data(), n);
      print("crba", k, M.data(), n * n); // column-major, as the Rust side prints M
      print("aba", k, ddq.data(), n);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Spatial arms (argv[2] == "spatial"): the arms of benches/spatial.rs from their DH parameters.

// One joint's Denavit-Hartenberg row (every joint revolute, theta offsets zero).
struct DhRow
{
  double a, alpha, d;
};

struct SpatialArmSpec
{
  const char * name;
  bool modified; // Craig's modified (proximal) DH, else standard (distal) DH
  std::vector<DhRow> rows;
  Eigen::Vector3d tool; // the tool frame's offset in the last link's frame (no rotation)
};

static std::vector<SpatialArmSpec> spatial_arms()
{
  const double h = M_PI / 2.;
  return {
    // PUMA 560, Corke's standard DH (examples/puma.rs).
    {"Puma560",
     false,
     {{0., h, 0.}, {0.4318, 0., 0.}, {0.0203, -h, 0.15005}, {0., h, 0.4318}, {0., -h, 0.},
      {0., 0., 0.}},
     Eigen::Vector3d::Zero()},
    // UR5, Universal Robots' standard DH.
    {"Ur5",
     false,
     {{0., h, 0.089159}, {-0.425, 0., 0.}, {-0.39225, 0., 0.}, {0., h, 0.10915},
      {0., -h, 0.09465}, {0., 0., 0.0823}},
     Eigen::Vector3d::Zero()},
    // Franka Panda, modified DH from Franka's documentation, flange 0.107 m along z.
    {"Panda",
     true,
     {{0., 0., 0.333}, {0., -h, 0.}, {0., h, 0.316}, {0.0825, h, 0.}, {-0.0825, -h, 0.384},
      {0., h, 0.}, {0.088, h, 0.}},
     Eigen::Vector3d(0., 0., 0.107)},
  };
}

// Rx(alpha) with the cosine and sine of multiples of pi/2 exact (0, 1, -1), as the derive has
// them.
static Eigen::Matrix3d rot_x(double alpha)
{
  auto snap = [](double x) {
    if (std::abs(x) < 1e-15)
      return 0.;
    if (std::abs(x - 1.) < 1e-15)
      return 1.;
    if (std::abs(x + 1.) < 1e-15)
      return -1.;
    return x;
  };
  const double c = snap(std::cos(alpha)), s = snap(std::sin(alpha));
  Eigen::Matrix3d r;
  r << 1., 0., 0., 0., c, -s, 0., s, c;
  return r;
}

// The chain of JointModelRZ joints, each placed by the constant part of the DH transforms
// between it and the previous joint, and an OP_FRAME "tool" on the last joint.
//   standard DH: T_i = Rz(q_i) B_i, B_i = Tz(d_i) Tx(a_i) Rx(alpha_i): joint 1 at the
//                identity, joint i at B_{i-1}, the tool at B_N Tool;
//   modified DH: T_i = A_i Rz(q_i) C_i, A_i = Rx(alpha_i) Tx(a_i), C_i = Tz(d_i): joint i at
//                C_{i-1} A_i (C_0 the identity), the tool at C_N Tool.
// Massless links: the frame Jacobian does not read inertias.
static pin::Model build_spatial(const SpatialArmSpec & arm, pin::FrameIndex & tool)
{
  pin::Model model;
  pin::SE3 carry = pin::SE3::Identity(); // the constant transform left over from the last row
  pin::JointIndex parent = 0;
  int k = 0;
  for (const DhRow & r : arm.rows)
  {
    ++k;
    pin::SE3 placement = carry;
    if (arm.modified)
    {
      placement = carry * pin::SE3(rot_x(r.alpha), Eigen::Vector3d(r.a, 0., 0.));
      carry = pin::SE3(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0., 0., r.d));
    }
    else
      carry = pin::SE3(rot_x(r.alpha), Eigen::Vector3d(r.a, 0., r.d));
    parent = model.addJoint(parent, pin::JointModelRZ(), placement, "joint" + std::to_string(k));
  }
  const pin::SE3 flange = carry * pin::SE3(Eigen::Matrix3d::Identity(), arm.tool);
  tool = model.addFrame(pin::Frame("tool", parent, flange, pin::OP_FRAME));
  return model;
}

static std::vector<Eigen::VectorXd> spatial_states(int n)
{
  std::vector<Eigen::VectorXd> q;
  for (int k = 0; k < NSTATES; ++k)
    q.push_back(state(n, 1000 + k, M_PI));
  return q;
}

// The tool pose (homogeneous 4x4) and the frame Jacobian at the first four states, by columns,
// for run.sh to compare with `cargo bench --bench spatial -- --values`; then the timing.
static void spatial_main(long calls)
{
  const std::vector<SpatialArmSpec> all = spatial_arms();
  std::printf("# checks (%s)\n", VARIANT);
  for (const SpatialArmSpec & arm : all)
  {
    pin::FrameIndex tool;
    pin::Model m = build_spatial(arm, tool);
    pin::Data d(m);
    const int n = m.nv;
    const std::vector<Eigen::VectorXd> qs = spatial_states(n);
    pin::Data::Matrix6x J = pin::Data::Matrix6x::Zero(6, n);
    auto print = [&](const char * op, int k, const double * x, int len) {
      std::printf("# value, %s, %s, %d,", arm.name, op, k);
      for (int i = 0; i < len; ++i)
        std::printf(" %.17g", x[i]);
      std::printf("\n");
    };
    for (int k = 0; k < 4; ++k)
    {
      pin::computeFrameJacobian(m, d, qs[k], tool, pin::LOCAL_WORLD_ALIGNED, J);
      const Eigen::Matrix4d pose = d.oMf[tool].toHomogeneousMatrix();
      print("pose", k, pose.data(), 16);
      print("jacobian", k, J.data(), 6 * n);
    }
  }

  std::printf("# variant=%s pinocchio=%s calls/round=%ld rounds=%d states=%d\n", VARIANT,
              PINOCCHIO_VERSION, calls, ROUNDS, NSTATES);
  std::printf("variant, N, op, wall ns/call, cpu ns/call\n");
  for (const SpatialArmSpec & arm : all)
  {
    pin::FrameIndex tool;
    pin::Model model = build_spatial(arm, tool);
    pin::Data data(model);
    const int n = model.nv;
    const std::vector<Eigen::VectorXd> qs = spatial_states(n);
    // Every column is written on each call (all joints support the tool): zeroed once.
    pin::Data::Matrix6x J = pin::Data::Matrix6x::Zero(6, n);
    const Timing t = time_op(
      [&](int k) {
        pin::computeFrameJacobian(model, data, qs[k], tool, pin::LOCAL_WORLD_ALIGNED, J);
        return data.oMf[tool].translation()[0] + J(0, n - 1);
      },
      calls);
    std::printf("%s, %d, %s/frame_jacobian, %.1f, %.1f\n", VARIANT, n, arm.name, t.wall, t.cpu);
    std::fflush(stdout);
  }
  std::printf("# checksum %.17g\n", checksum);
}

// ---------------------------------------------------------------------------------------------
// Spatial dynamics (argv[2] == "spatial-dynamics"): the arms of benches/spatial_dynamics.rs
// with their mass properties; rnea, crba, nonLinearEffects and aba.

// The PUMA 560 of examples/puma.rs: Corke's standard DH rows (a, alpha, d) and each link's
// mass, centre of mass and inertia about it (xx, yy, zz, xy, xz, yz) in the link's DH frame.
struct DhLink
{
  DhRow row;
  double mass;
  Eigen::Vector3d com;
  double inertia[6];
};

static std::vector<DhLink> puma_links()
{
  const double h = M_PI / 2.;
  return {
    {{0., h, 0.}, 0., {0., 0., 0.}, {0., 0.35, 0., 0., 0., 0.}},
    {{0.4318, 0., 0.}, 17.4, {-0.3638, 0.006, 0.2275}, {0.13, 0.524, 0.539, 0., 0., 0.}},
    {{0.0203, -h, 0.15005}, 4.8, {-0.0203, -0.0141, 0.07}, {0.066, 0.086, 0.0125, 0., 0., 0.}},
    {{0., h, 0.4318}, 0.82, {0., 0.019, 0.}, {1.8e-3, 1.3e-3, 1.8e-3, 0., 0., 0.}},
    {{0., -h, 0.}, 0.34, {0., 0., 0.}, {0.3e-3, 0.4e-3, 0.3e-3, 0., 0., 0.}},
    {{0., 0., 0.}, 0.09, {0., 0., 0.032}, {0.15e-3, 0.15e-3, 0.04e-3, 0., 0., 0.}},
  };
}

// One URDF joint and its link: the joint's origin (xyz, rpy), its axis ('x', 'y' or 'z', all
// positive here), the link's mass, centre of mass and inertia about it (xx, yy, zz, xy, xz,
// yz) in the link frame. Printed by bench/pinocchio/urdf_arms.py from example-robot-data's
// URDFs (the Panda's hand and fingers merged into link 7), as in benches/spatial_dynamics.rs.
struct UrdfLink
{
  double xyz[3], rpy[3];
  char axis;
  double mass, com[3], inertia[6];
};

static std::vector<UrdfLink> ur5_links()
{
  const double H = M_PI / 2.;
  return {
     {{0, 0, 0.089159}, {0, 0, 0}, 'z', 3.7, {0, 0, 0},
      {0.010267495893, 0.010267495893, 0.00666, 0, 0, 0}},
     {{0, 0.13585, 0}, {0, H, 0}, 'y', 8.393, {0, 0, 0.28},
      {0.22689067591, 0.22689067591, 0.0151074, 0, 0, 0}},
     {{0, -0.1197, 0.425}, {0, 0, 0}, 'y', 2.275, {0, 0, 0.25},
      {0.049443313556, 0.049443313556, 0.004095, 0, 0, 0}},
     {{0, 0, 0.39225}, {0, H, 0}, 'y', 1.219, {0, 0, 0},
      {0.111172755531, 0.111172755531, 0.21942, 0, 0, 0}},
     {{0, 0.093, 0}, {0, 0, 0}, 'z', 1.219, {0, 0, 0},
      {0.111172755531, 0.111172755531, 0.21942, 0, 0, 0}},
     {{0, 0, 0.09465}, {0, 0, 0}, 'y', 0.1879, {0, 0, 0},
      {0.0171364731454, 0.0171364731454, 0.033822, 0, 0, 0}},
  };
}

static std::vector<UrdfLink> panda_links()
{
  const double H = M_PI / 2.;
  return {
     {{0, 0, 0.333}, {0, 0, 0}, 'z', 4.970684, {0.003875, 0.002081, -0.04762},
      {0.70337, 0.70661, 0.009117, -0.000139, 0.006772, 0.019169}},
     {{0, 0, 0}, {-H, 0, 0}, 'z', 0.646926, {-0.003141, -0.02872, 0.003495},
      {0.007962, 0.02811, 0.025995, -0.003925, 0.010254, 0.000704}},
     {{0, -0.316, 0}, {H, 0, 0}, 'z', 3.228604, {0.027518, 0.039252, -0.066502},
      {0.037242, 0.036155, 0.01083, -0.004761, -0.011396, -0.012805}},
     {{0.0825, 0, 0}, {H, 0, 0}, 'z', 3.587895, {-0.05317, 0.104419, 0.027454},
      {0.025853, 0.019552, 0.028323, 0.007796, -0.001332, 0.008641}},
     {{-0.0825, 0.384, 0}, {-H, 0, 0}, 'z', 1.225946, {-0.011953, 0.041065, -0.038437},
      {0.035549, 0.029474, 0.008627, -0.002117, -0.004037, 0.000229}},
     {{0, 0, 0}, {H, 0, 0}, 'z', 1.666555, {0.060149, -0.014117, -0.010517},
      {0.001964, 0.004354, 0.005433, 0.000109, -0.001158, 0.000341}},
     {{0.088, 0, 0}, {H, 0, 0}, 'z', 1.4955219999999998, {0.0017208742976286568, 0.001360354417161231, 0.1004852811486558},
      {0.016529853712634632, 0.014107248642161837, 0.006676955556640956, 0.0003948922971191779, -0.0007066957106145017, -0.001051105327046708}},
  };
}

// cos and sin with those of multiples of pi/2 exact (0, 1, -1), as the derive has them.
static double snap(double x)
{
  for (double v : {0., 1., -1.})
    if (std::abs(x - v) < 1e-15)
      return v;
  return x;
}

// URDF's roll-pitch-yaw: Rz(yaw) Ry(pitch) Rx(roll).
static Eigen::Matrix3d rpy_matrix(const double rpy[3])
{
  const double cr = snap(std::cos(rpy[0])), sr = snap(std::sin(rpy[0]));
  const double cp = snap(std::cos(rpy[1])), sp = snap(std::sin(rpy[1]));
  const double cy = snap(std::cos(rpy[2])), sy = snap(std::sin(rpy[2]));
  Eigen::Matrix3d x, y, z;
  x << 1., 0., 0., 0., cr, -sr, 0., sr, cr;
  y << cp, 0., sp, 0., 1., 0., -sp, 0., cp;
  z << cy, -sy, 0., sy, cy, 0., 0., 0., 1.;
  return z * y * x;
}

static pin::Inertia body_inertia(double mass, const Eigen::Vector3d & com, const double i[6])
{
  // Symmetric3(xx, xy, yy, xz, yz, zz), about the centre of mass.
  return pin::Inertia(mass, com, pin::Symmetric3(i[0], i[3], i[1], i[4], i[5], i[2]));
}

// The PUMA: JointModelRZ joints placed as in build_spatial (standard DH: joint i at B_{i-1}),
// each link's inertia placed in its joint's frame by B_i = Tz(d_i) Tx(a_i) Rx(alpha_i), which
// carries the joint's frame to the link's DH frame (as bench/pinocchio/spatial_dynamics.py).
static pin::Model build_puma_dynamics()
{
  pin::Model model;
  model.gravity.linear(Eigen::Vector3d(0., 0., -9.81));
  pin::SE3 carry = pin::SE3::Identity();
  pin::JointIndex parent = 0;
  int k = 0;
  for (const DhLink & l : puma_links())
  {
    ++k;
    parent = model.addJoint(parent, pin::JointModelRZ(), carry, "joint" + std::to_string(k));
    carry = pin::SE3(rot_x(l.row.alpha), Eigen::Vector3d(l.row.a, 0., l.row.d));
    model.appendBodyToJoint(parent, body_inertia(l.mass, l.com, l.inertia), carry);
  }
  return model;
}

// A URDF chain as Pinocchio's URDF parser builds it: joint i placed at its origin in the
// previous joint's (= link's) frame, a JointModelRX/RY/RZ for an axis along x/y/z, the
// link's inertia in the joint's frame. Gravity (0, 0, -9.81), Pinocchio's default.
static pin::Model build_urdf(const std::vector<UrdfLink> & links)
{
  pin::Model model;
  model.gravity.linear(Eigen::Vector3d(0., 0., -9.81));
  pin::JointIndex parent = 0;
  int k = 0;
  for (const UrdfLink & l : links)
  {
    ++k;
    const pin::SE3 placement(rpy_matrix(l.rpy), Eigen::Vector3d(l.xyz[0], l.xyz[1], l.xyz[2]));
    const std::string name = "joint" + std::to_string(k);
    switch (l.axis)
    {
    case 'x':
      parent = model.addJoint(parent, pin::JointModelRX(), placement, name);
      break;
    case 'y':
      parent = model.addJoint(parent, pin::JointModelRY(), placement, name);
      break;
    default:
      parent = model.addJoint(parent, pin::JointModelRZ(), placement, name);
    }
    model.appendBodyToJoint(
      parent, body_inertia(l.mass, Eigen::Vector3d(l.com[0], l.com[1], l.com[2]), l.inertia),
      pin::SE3::Identity());
  }
  return model;
}

// Each arm with, where its links' frames (those of benches/spatial_dynamics.rs, in which the
// derive's standard parameters are) are not Pinocchio's joint frames, each link's frame in its
// joint's frame: the PUMA's DH frame i is B_i in joint i's frame. The URDF arms' link frames
// are the joint frames (none listed).
struct DynamicsArm
{
  const char * name;
  pin::Model model;
  std::vector<pin::SE3> link_frames;
};

static std::vector<pin::SE3> puma_link_frames()
{
  std::vector<pin::SE3> frames;
  for (const DhLink & l : puma_links())
    frames.push_back(pin::SE3(rot_x(l.row.alpha), Eigen::Vector3d(l.row.a, 0., l.row.d)));
  return frames;
}

static std::vector<DynamicsArm> dynamics_arms()
{
  return {
    {"Puma560", build_puma_dynamics(), puma_link_frames()},
    {"Ur5", build_urdf(ur5_links()), {}},
    {"Panda", build_urdf(panda_links()), {}},
  };
}

// The ten dynamic parameters [m, m c, Ixx, Ixy, Iyy, Ixz, Iyz, Izz] of a body given in frame B
// as those of the same body in B's parent frame: linear, A theta_B. Its columns by differences
// around a unit body (exact up to rounding, the map being linear), through Pinocchio's own
// Inertia::FromDynamicParameters, SE3::act and toDynamicParameters.
static Eigen::Matrix<double, 10, 10> parameters_in_parent(const pin::SE3 & B)
{
  Eigen::Matrix<double, 10, 1> unit;
  unit << 1., 0., 0., 0., 1., 0., 1., 0., 0., 1.;
  auto moved = [&](const Eigen::Matrix<double, 10, 1> & theta) -> Eigen::Matrix<double, 10, 1> {
    return B.act(pin::Inertia::FromDynamicParameters(theta)).toDynamicParameters();
  };
  const Eigen::Matrix<double, 10, 1> at_unit = moved(unit);
  Eigen::Matrix<double, 10, 10> A;
  for (int j = 0; j < 10; ++j)
    A.col(j) = moved(unit + Eigen::Matrix<double, 10, 1>::Unit(j)) - at_unit;
  return A;
}

// computeJointTorqueRegressor's Y (parameters in the joint frames) for the parameters in the
// arm's link frames: Y blockdiag(A_1, ..., A_N), Y itself for an arm whose link frames are its
// joint frames.
static Eigen::MatrixXd regressor_in_link_frames(const DynamicsArm & arm, const Eigen::MatrixXd & Y)
{
  if (arm.link_frames.empty())
    return Y;
  Eigen::MatrixXd out(Y.rows(), Y.cols());
  for (int i = 0; i < int(arm.link_frames.size()); ++i)
    out.middleCols<10>(10 * i) = Y.middleCols<10>(10 * i) * parameters_in_parent(arm.link_frames[i]);
  return out;
}

// benches/spatial_dynamics.rs's states: q from seed 1000 + 3k in [-pi, pi), v from
// 1001 + 3k and a (aba's tau) from 1002 + 3k in [-1, 1).
static States dynamics_states(int n)
{
  States st;
  for (int k = 0; k < NSTATES; ++k)
  {
    st.q.push_back(state(n, 1000 + 3 * k, M_PI));
    st.v.push_back(state(n, 1001 + 3 * k, 1.));
    st.a.push_back(state(n, 1002 + 3 * k, 1.));
  }
  return st;
}

// crba in either convention, both triangles (crba fills the upper one).
static Eigen::MatrixXd full_crba(
  const pin::Model & m, pin::Data & d, const Eigen::VectorXd & q, pin::Convention c)
{
  Eigen::MatrixXd M = pin::crba(m, d, Ref(q), c);
  M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
  return M;
}

// The accelerations as the generated forward_dynamics gets them: crba, nonLinearEffects, then
// Pinocchio's sparse (tree) Cholesky factorisation of M (cholesky::decompose, from crba's
// upper triangle) and its solve of M qdd = tau - nle, in place in `x`.
static double crba_nle_cholesky(
  const pin::Model & m, pin::Data & d, const Eigen::VectorXd & q, const Eigen::VectorXd & v,
  const Eigen::VectorXd & tau, Eigen::VectorXd & x)
{
  pin::crba(m, d, Ref(q));
  pin::nonLinearEffects(m, d, q, v);
  pin::cholesky::decompose(m, d);
  x = tau - d.nle;
  pin::cholesky::solve(m, d, x);
  return x[m.nv - 1];
}

// Per arm, at the first four states: rnea, crba (both triangles, by columns), nonLinearEffects,
// crba then nonLinearEffects (M by columns, then nle) and aba (a as tau), crba and aba in both
// conventions (`_world` for Convention::WORLD), and the accelerations by crba,
// nonLinearEffects and the Cholesky solve (`crba+nle+cholesky`), for run.sh to compare with the
// generated code's (`cargo bench --bench spatial_dynamics -- --values`), with
// computeRNEADerivatives (dtau_dq, dtau_dv) and computeABADerivatives (ddq_dq, ddq_dv, Minv
// symmetrised), all by columns, and computeJointTorqueRegressor by columns, in the arm's link
// frames (`regressor`: for the PUMA Y blockdiag(A_i), see regressor_in_link_frames, and then
// also Y itself as `regressor_joint_frames`); then the timing of rnea, crba, aba and
// crba + nonLinearEffects, crba and aba in both conventions, of crba + nonLinearEffects + the
// Cholesky solve, of computeRNEADerivatives and computeABADerivatives, and of
// computeJointTorqueRegressor (Y itself, no change of frames).
static void spatial_dynamics_main(long calls)
{
  std::printf("# checks (%s)\n", VARIANT);
  for (DynamicsArm & arm : dynamics_arms())
  {
    const pin::Model & m = arm.model;
    pin::Data d(m);
    const int n = m.nv;
    const States s = dynamics_states(n);
    auto print = [&](const char * op, int k, const Eigen::VectorXd & x) {
      std::printf("# value, %s, %s, %d,", arm.name, op, k);
      for (int i = 0; i < x.size(); ++i)
        std::printf(" %.17g", x[i]);
      std::printf("\n");
    };
    auto flat = [](const Eigen::MatrixXd & M) {
      return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(M.data(), M.size()));
    };
    for (int k = 0; k < 4; ++k)
    {
      const Eigen::VectorXd tau = pin::rnea(m, d, s.q[k], s.v[k], s.a[k]);
      print("rnea", k, tau);
      for (pin::Convention c : {pin::Convention::LOCAL, pin::Convention::WORLD})
      {
        const std::string sfx = c == pin::Convention::WORLD ? "_world" : "";
        const Eigen::MatrixXd M = full_crba(m, d, s.q[k], c);
        const Eigen::VectorXd nle = pin::nonLinearEffects(m, d, s.q[k], s.v[k]);
        Eigen::VectorXd both(n * n + n);
        both << flat(M), nle;
        print(("crba" + sfx).c_str(), k, flat(M));
        print(("crba" + sfx + "+nle").c_str(), k, both);
        print(("aba" + sfx).c_str(), k, pin::aba(m, d, Ref(s.q[k]), Ref(s.v[k]), Ref(s.a[k]), c));
        if (c == pin::Convention::LOCAL)
        {
          print("nle", k, nle);
          Eigen::VectorXd x(n);
          crba_nle_cholesky(m, d, s.q[k], s.v[k], s.a[k], x);
          print("crba+nle+cholesky", k, x);
          // The derivatives: dtau_dq then dtau_dv (by columns); ddq_dq, ddq_dv then Minv
          // (by columns, Minv symmetrised from the upper triangle Pinocchio fills).
          pin::computeRNEADerivatives(m, d, s.q[k], s.v[k], s.a[k]);
          Eigen::VectorXd rd(2 * n * n);
          rd << flat(d.dtau_dq), flat(d.dtau_dv);
          print("rnea_derivatives", k, rd);
          pin::computeABADerivatives(m, d, s.q[k], s.v[k], s.a[k]);
          Eigen::MatrixXd minv = d.Minv;
          minv.triangularView<Eigen::StrictlyLower>() = minv.transpose();
          Eigen::VectorXd ad(3 * n * n);
          ad << flat(d.ddq_dq), flat(d.ddq_dv), flat(minv);
          print("aba_derivatives", k, ad);
          // The regressor: Pinocchio's, then in the link frames.
          const Eigen::MatrixXd Y = pin::computeJointTorqueRegressor(m, d, s.q[k], s.v[k], s.a[k]);
          const Eigen::MatrixXd Yl = regressor_in_link_frames(arm, Y);
          print("regressor", k, flat(Yl));
          if (!arm.link_frames.empty())
            print("regressor_joint_frames", k, flat(Y));
          if (k == 0)
          {
            std::printf(
              "# %s (N=%d): |M a + nle - rnea| = %.3g\n", arm.name, n,
              (M * s.a[k] + nle - tau).cwiseAbs().maxCoeff());
            // Y theta with theta in the joint frames (Pinocchio's inertias), and Y A theta_l
            // with theta_l each link's inertia in its own frame: B_i^-1 acting on Pinocchio's.
            Eigen::VectorXd theta(10 * n), theta_l(10 * n);
            for (int i = 0; i < n; ++i)
            {
              const pin::Inertia & I = m.inertias[i + 1];
              theta.segment<10>(10 * i) = I.toDynamicParameters();
              theta_l.segment<10>(10 * i) =
                (arm.link_frames.empty() ? I : arm.link_frames[i].actInv(I)).toDynamicParameters();
            }
            std::printf(
              "# %s (N=%d): |Y theta - rnea| = %.3g, |Y_link theta_link - rnea| = %.3g\n",
              arm.name, n, (Y * theta - tau).cwiseAbs().maxCoeff(),
              (Yl * theta_l - tau).cwiseAbs().maxCoeff());
          }
        }
      }
    }
  }

  std::printf("# variant=%s pinocchio=%s calls/round=%ld rounds=%d states=%d\n", VARIANT,
              PINOCCHIO_VERSION, calls, ROUNDS, NSTATES);
  std::printf("variant, N, op, wall ns/call, cpu ns/call\n");
  for (DynamicsArm & arm : dynamics_arms())
  {
    const pin::Model & model = arm.model;
    pin::Data data(model);
    const int n = model.nv;
    const States s = dynamics_states(n);
    auto report = [&](const char * op, Timing t) {
      std::printf("%s, %d, %s/%s, %.1f, %.1f\n", VARIANT, n, arm.name, op, t.wall, t.cpu);
      std::fflush(stdout);
    };
    report("rnea", time_op(
                     [&](int k) { return pin::rnea(model, data, s.q[k], s.v[k], s.a[k])[0]; },
                     calls));
    for (pin::Convention c : {pin::Convention::LOCAL, pin::Convention::WORLD})
    {
      const bool world = c == pin::Convention::WORLD;
      report(world ? "crba_world" : "crba",
             time_op([&](int k) { return pin::crba(model, data, Ref(s.q[k]), c)(0, n - 1); },
                     calls));
      report(world ? "aba_world" : "aba",
             time_op(
               [&](int k) {
                 return pin::aba(model, data, Ref(s.q[k]), Ref(s.v[k]), Ref(s.a[k]), c)[n - 1];
               },
               calls));
      report(world ? "crba_world+nle" : "crba+nle",
             time_op(
               [&](int k) {
                 pin::crba(model, data, Ref(s.q[k]), c);
                 pin::nonLinearEffects(model, data, s.q[k], s.v[k]);
                 return data.M(0, n - 1) + data.nle[0];
               },
               calls));
    }
    Eigen::VectorXd x(n);
    report("crba+nle+cholesky",
           time_op([&](int k) { return crba_nle_cholesky(model, data, s.q[k], s.v[k], s.a[k], x); },
                   calls));
    report("rnea_derivatives", time_op(
                                 [&](int k) {
                                   pin::computeRNEADerivatives(model, data, s.q[k], s.v[k], s.a[k]);
                                   return data.dtau_dq(0, n - 1) + data.dtau_dv(0, 0);
                                 },
                                 calls));
    report("aba_derivatives", time_op(
                                [&](int k) {
                                  pin::computeABADerivatives(model, data, s.q[k], s.v[k], s.a[k]);
                                  return data.ddq_dq(n - 1, 0) + data.ddq_dv(0, 0) + data.Minv(0, n - 1);
                                },
                                calls));
    report("regressor", time_op(
                          [&](int k) {
                            return pin::computeJointTorqueRegressor(
                              model, data, s.q[k], s.v[k], s.a[k])(n - 1, 10 * n - 1);
                          },
                          calls));
  }
  std::printf("# checksum %.17g\n", checksum);
}

int main(int argc, char ** argv)
{
  const long calls = argc > 1 ? std::atol(argv[1]) : 200000;
  if (argc > 2 && std::string(argv[2]) == "spatial")
  {
    spatial_main(calls);
    return 0;
  }
  if (argc > 2 && std::string(argv[2]) == "spatial-dynamics")
  {
    spatial_dynamics_main(calls);
    return 0;
  }
  const bool prismatic = argc > 2 && std::string(argv[2]) == "prismatic";
  const std::vector<Arm> all = prismatic ? prismatic_arms() : arms();
  if (prismatic)
    prismatic_checks(all);
  else
    checks(all);

  std::printf("# variant=%s pinocchio=%s calls/round=%ld rounds=%d states=%d\n", VARIANT,
              PINOCCHIO_VERSION, calls, ROUNDS, NSTATES);
  std::printf("variant, N, op, wall ns/call, cpu ns/call\n");
  for (const Arm & arm : all)
  {
    const int n = int(arm.links.size());
    pin::Model model = build(arm);
    pin::Data data(model);
    const States s = states(n);
    // The prismatic set has two arms of each N: the op is named `ARM/op` there.
    auto report = [&](const char * op, Timing t) {
      const std::string name = prismatic ? std::string(arm.name) + "/" + op : std::string(op);
      std::printf("%s, %d, %s, %.1f, %.1f\n", VARIANT, n, name.c_str(), t.wall, t.cpu);
      std::fflush(stdout);
    };

    if (!prismatic)
      report("regressor", time_op(
                            [&](int k) {
                              return pin::computeJointTorqueRegressor(
                                model, data, s.q[k], s.v[k], s.a[k])(n - 1, 10 * n - 1);
                            },
                            calls));
    report("rnea", time_op(
                     [&](int k) { return pin::rnea(model, data, s.q[k], s.v[k], s.a[k])[0]; },
                     calls));
    report("crba", time_op(
                     [&](int k) { return pin::crba(model, data, Ref(s.q[k]))(0, n - 1); }, calls));
    report("aba", time_op(
                    [&](int k) {
                      return pin::aba(model, data, Ref(s.q[k]), Ref(s.v[k]), Ref(s.a[k]))[n - 1];
                    },
                    calls));
    if (prismatic)
      continue;
    report("rnea_derivatives", time_op(
                                 [&](int k) {
                                   pin::computeRNEADerivatives(model, data, s.q[k], s.v[k], s.a[k]);
                                   return data.dtau_dq(0, n - 1) + data.dtau_dv(0, 0);
                                 },
                                 calls));
    report("aba_derivatives", time_op(
                                [&](int k) {
                                  pin::computeABADerivatives(model, data, s.q[k], s.v[k], s.a[k]);
                                  return data.ddq_dq(n - 1, 0) + data.ddq_dv(0, 0);
                                },
                                calls));
  }
  std::printf("# checksum %.17g\n", checksum);
  return 0;
}
