//! Independent numeric reference implementations of planar-arm dynamics and kinematics.
//!
//! Everything here is plain `f64` arithmetic written from first principles (Newton-Euler
//! mechanics and Featherstone's spatial-vector algorithms specialised to the plane). It shares
//! no code with the symbolic Lagrangian path of `#[derive(PlanarArm)]`, so the tests, the
//! benchmarks and the `paper` example use it as the ground truth the generated code is checked
//! and timed against. Every function takes the arm as a [`Model`]: links, gravity, payload.
//!
//! Conventions are those of the crate: `q[0]` is link 1's angle from +x and `q[i]` (i > 0) is
//! link i+1's angle relative to link i, so the absolute angle of link i+1 is
//! `phi_i = q[0] + ... + q[i]` and its direction `u_i = (cos phi_i, sin phi_i)`; joint 1 sits
//! at the origin; gravity of magnitude `model.gravity` acts along -y. A link's centre of mass
//! `com = (cx, cy)` is in its own frame, at `joint_i + cx u_i + cy perp(u_i)` in the world
//! (`perp` turns by +90 degrees); the payload's is at `tip + R(phi_N) payload.com`.
//!
//! The equations of motion are
//!
//! ```text
//! tau = M(q) qdd + c(q, qd) + g(q) + f(qd)
//! ```
//!
//! with `M` the mass matrix including each joint's armature on its diagonal, `c` the
//! velocity-product torques, `g = dV/dq` the gravity torques and
//! `f_i = damping_i qd_i + frictionloss_i sign(qd_i)` the joint friction ([`friction`];
//! `sign(0) = 0`). These are MuJoCo's joint `armature`, `damping` and `frictionloss`.
//! [`bias_forces`] is `c + g + f`; Pinocchio's `nonLinearEffects` is `c + g`.
//!
//! # Algorithms and cost
//!
//! All functions are generic over the number of links `N`, work on fixed-size arrays and
//! nalgebra `SVector`/`SMatrix` values, never allocate, never panic, and evaluate exactly one
//! `sin_cos` per joint (of the cumulative absolute angle). The payload enters each algorithm
//! as one more body rigidly fixed beyond the tip (the Newton-Euler recursion starts from its
//! inertial wrench at the tip, the composite and articulated inertias start from its
//! inertia), not through [`Model::rigid_links`], which the tests check against.
//!
//! | function | algorithm | cost |
//! |---|---|---|
//! | [`inverse_dynamics`], [`bias_forces`], [`coriolis`] | recursive Newton-Euler (RNEA): outward pass for angular velocity/acceleration and joint/COM linear accelerations (gravity as a base acceleration `+g` along +y), inward pass for joint forces and moments; armature and friction added per joint | O(N) |
//! | [`gravity_torques`] | inward accumulation of composite mass and first moment (statics) | O(N) |
//! | [`friction`] | per joint | O(N) |
//! | [`mass_matrix`] | composite rigid body algorithm (CRBA) with planar composite inertias (mass, first moment, rotational inertia about each joint), armature on the diagonal | O(N^2) |
//! | [`forward_dynamics`] | articulated body algorithm (ABA) with 3x3 planar spatial inertias `[angular; x; y]`, all expressed about the world origin so that no inter-link transforms are needed; armature in the joint-space articulated inertia; never forms `M` | O(N) |
//! | [`forward_dynamics_crba`] | CRBA + RNEA bias + Cholesky solve | O(N^3) |
//! | [`kinetic_energy`], [`potential_energy`] | direct sums over COM velocities / heights, payload as its own body | O(N) |
//! | [`tip_position`], [`joint_positions`], [`jacobian`] | forward kinematics; the Jacobian column of joint j is `perp(tip - joint_j)` | O(N) / O(N) / O(N) |
//! | [`regressor`] | the torques of each body's four inertial parameters per unit value, by one outward Newton-Euler pass and each body's wrench moved to every joint before it | O(N^2) |
//! | [`regressor_local`] | the same by Pinocchio's `computeJointTorqueRegressor` algorithm: each body's regressor in its own frame, moved inwards joint by joint | O(N^2) |

use nalgebra::{Matrix3, Point2, SMatrix, SVector, Vector2, Vector3};
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use crate::Model;

mod regressor;

pub use regressor::{link_parameters, payload_parameters, regressor, regressor_local, Regressor};

/// Unit vectors `(cos phi_i, sin phi_i)` along each link, from the cumulative absolute angles.
#[inline(always)]
fn link_directions<const N: usize>(q: &SVector<f64, N>) -> [Vector2<f64>; N] {
    // A plain loop: mapping over `absolute_angles` instead measured 2-6 % slower, and the
    // reference is not to be pessimised.
    let mut dirs = [Vector2::zeros(); N];
    let mut phi = 0.0;
    for (dir, &qi) in dirs.iter_mut().zip(q.iter()) {
        phi += qi;
        let (s, c) = phi.sin_cos();
        *dir = Vector2::new(c, s);
    }
    dirs
}

/// `q1, q1 + q2, ...`: each link's angle from the base x axis, for one batched `sin_cos`.
#[inline(always)]
fn absolute_angles<const N: usize>(q: &SVector<f64, N>) -> [f64; N] {
    let mut phi = 0.0;
    core::array::from_fn(|i| {
        phi += q[i];
        phi
    })
}

/// The direction of the last link, the frame the payload is fixed in (+x with no links).
#[inline(always)]
fn last_direction<const N: usize>(dirs: &[Vector2<f64>; N]) -> Vector2<f64> {
    dirs.last().copied().unwrap_or_else(Vector2::x)
}

/// `a` rotated by +90 degrees.
#[inline(always)]
fn perp(a: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-a.y, a.x)
}

/// The vector `c`, given in the frame of a link with direction `u`, in the world frame:
/// `c.x u + c.y perp(u)`.
#[inline(always)]
fn in_world(u: Vector2<f64>, c: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(c.x * u.x - c.y * u.y, c.x * u.y + c.y * u.x)
}

/// The scalar (z) component of the planar cross product `a x b`.
#[inline(always)]
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// The sign of `x` with `sign(0) = sign(-0) = 0` (unlike `f64::signum`); NaN stays NaN.
#[inline(always)]
fn sign(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x.signum()
    }
}

/// Recursive Newton-Euler on precomputed link directions: `M(q) qdd + c(q, qd) + g(q)` for
/// gravity of magnitude `gravity`, armature included, friction not.
#[inline(always)]
fn rnea_dirs<const N: usize>(
    model: &Model<N>,
    gravity: f64,
    dirs: &[Vector2<f64>; N],
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let links = &model.links;
    // Outward pass. Gravity is modelled by accelerating the base upwards at `gravity`.
    let mut alpha = [0.0; N];
    let mut r_com = [Vector2::zeros(); N];
    let mut a_com = [Vector2::zeros(); N];
    let mut a_joint = Vector2::new(0.0, gravity);
    let mut omega = 0.0;
    let mut omega_dot = 0.0;
    for i in 0..N {
        omega += qd[i];
        omega_dot += qdd[i];
        let u = dirs[i];
        let r = in_world(u, links[i].com);
        // Acceleration of a point at `r` from the link's joint, relative to the joint:
        // tangential `omega_dot * perp(r)` plus centripetal `-omega^2 r`.
        a_com[i] = a_joint + perp(r) * omega_dot - r * (omega * omega);
        a_joint += (perp(u) * omega_dot - u * (omega * omega)) * links[i].length;
        alpha[i] = omega_dot;
        r_com[i] = r;
    }

    // Inward pass: `force` is the force link i exerts on what lies beyond joint i+1 (the tip
    // for the last link), `moment` the moment it exerts there; on exit from iteration i they
    // refer to joint i. They start as the payload's inertial wrench about the tip, the payload
    // turning with the last link (`a_joint` is the tip's acceleration by now).
    let payload = &model.payload;
    let r = in_world(last_direction(dirs), payload.com);
    let mut force = (a_joint + perp(r) * omega_dot - r * (omega * omega)) * payload.mass;
    let mut moment = payload.inertia * omega_dot + cross(r, force);
    let mut tau = SVector::zeros();
    for i in (0..N).rev() {
        let link = &links[i];
        let u = dirs[i];
        let f_com = a_com[i] * link.mass;
        // Euler's equation about joint i (a point with its own acceleration, hence the COM term).
        moment += link.inertia * alpha[i] + cross(r_com[i], f_com) + link.length * cross(u, force);
        force += f_com;
        // The rotor's torque acts on the joint alone; it is not transmitted inwards.
        tau[i] = moment + link.armature * qdd[i];
    }
    tau
}

/// Composite rigid body algorithm on precomputed link directions.
#[inline(always)]
fn crba_dirs<const N: usize>(model: &Model<N>, dirs: &[Vector2<f64>; N]) -> SMatrix<f64, N, N> {
    let links = &model.links;
    let mut m = SMatrix::<f64, N, N>::zeros();
    // Composite body of links j..N and the payload about joint j: mass, first moment (world
    // frame, relative to joint j) and rotational inertia. It starts as the payload about the
    // tip.
    let payload = &model.payload;
    let mut mass = payload.mass;
    let mut first = in_world(last_direction(dirs), payload.com) * payload.mass;
    let mut rot = payload.inertia + payload.mass * payload.com.norm_squared();
    for j in (0..N).rev() {
        let link = &links[j];
        let u = dirs[j];
        // Shift the composite beyond joint j+1 from joint j+1 to joint j (offset d = l_j u_j),
        // then add link j itself.
        let d = u * link.length;
        rot += link.inertia_about_joint() + 2.0 * d.dot(&first) + mass * link.length * link.length;
        first += in_world(u, link.com) * link.mass + d * mass;
        mass += link.mass;

        // Unit rate at joint j gives the composite angular momentum `rot` about joint j and
        // linear momentum `perp(first)`; its moment about joint i < j adds
        // `(p_j - p_i) x perp(first) = (p_j - p_i) . first`, accumulated link by link. The
        // rotor turns with joint j alone: its armature is on the diagonal only.
        let mut mij = rot;
        m[(j, j)] = rot + link.armature;
        for i in (0..j).rev() {
            mij += links[i].length * dirs[i].dot(&first);
            m[(i, j)] = mij;
            m[(j, i)] = mij;
        }
    }
    m
}

/// Joint torques `tau = M(q) qdd + c(q, qd) + g(q) + f(qd)`: the recursive Newton-Euler
/// algorithm for the bodies, plus each joint's armature torque `armature_i qdd_i` and its
/// [`friction`].
///
/// O(N): an outward pass computes each link's angular velocity and acceleration and the linear
/// accelerations of its joint and centre of mass (gravity enters as an upward base acceleration);
/// an inward pass sums forces and moments about each joint, starting from the payload's.
#[inline]
#[must_use]
pub fn inverse_dynamics<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(model, model.gravity, &link_directions(q), qd, qdd) + friction(model, qd)
}

/// [`inverse_dynamics`] with the absolute link angles' sines and cosines from
/// [`trig::sin_cos`](crate::trig::sin_cos), all in one call, instead of one `f64::sin_cos` per
/// link: the same recursion with the generated code's trigonometry, so that the benchmarks can
/// tell what the generated code gains from its trigonometry and what from its arithmetic.
#[inline]
#[must_use]
pub fn inverse_dynamics_batched_trig<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let dirs = crate::trig::sin_cos(absolute_angles(q)).map(|(s, c)| Vector2::new(c, s));
    rnea_dirs(model, model.gravity, &dirs, qd, qdd) + friction(model, qd)
}

/// The joint-space mass matrix `M(q)` by the composite rigid body algorithm, each joint's
/// armature on its diagonal.
///
/// O(N^2): one inward pass builds the composite mass, first moment and rotational inertia about
/// each joint; the off-diagonal entries follow by shifting each composite's momentum inwards.
#[inline]
#[must_use]
pub fn mass_matrix<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SMatrix<f64, N, N> {
    crba_dirs(model, &link_directions(q))
}

/// The bias forces `c(q, qd) + g(q) + f(qd)`: [`inverse_dynamics`] with `qdd = 0`.
///
/// Pinocchio's `nonLinearEffects` and MuJoCo's `qfrc_bias` are `c + g`, without the friction.
#[inline]
#[must_use]
pub fn bias_forces<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(
        model,
        model.gravity,
        &link_directions(q),
        qd,
        &SVector::zeros(),
    ) + friction(model, qd)
}

/// The gravity torques `g(q) = dV/dq`: the joint torques that hold the arm still.
///
/// O(N): joint i must support the weight of links i..N and the payload, whose moment about
/// joint i is `gravity` times the horizontal first moment of that composite body.
#[inline]
#[must_use]
pub fn gravity_torques<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SVector<f64, N> {
    let dirs = link_directions(q);
    let payload = &model.payload;
    let mut tau = SVector::zeros();
    let mut mass = payload.mass;
    let mut first_x = payload.mass * in_world(last_direction(&dirs), payload.com).x;
    for i in (0..N).rev() {
        let link = &model.links[i];
        let u = dirs[i];
        first_x += link.mass * in_world(u, link.com).x + mass * link.length * u.x;
        mass += link.mass;
        tau[i] = model.gravity * first_x;
    }
    tau
}

/// The velocity-product (Coriolis and centrifugal) torques `c(q, qd)`: the rigid-body part of
/// [`inverse_dynamics`] with zero gravity, `qdd = 0` and no friction.
#[inline]
#[must_use]
pub fn coriolis<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(model, 0.0, &link_directions(q), qd, &SVector::zeros())
}

/// The joint friction torques `f_i = damping_i qd_i + frictionloss_i sign(qd_i)`, with
/// `sign(0) = 0`: viscous plus Coulomb friction, opposing the motion when subtracted from the
/// motor torque (they are part of `tau = M qdd + c + g + f`).
///
/// A joint at rest feels no Coulomb friction here (MuJoCo instead solves for static friction
/// as a constraint). NaN in `qd` gives NaN in the result.
#[inline]
#[must_use]
pub fn friction<const N: usize>(model: &Model<N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
    let mut f = SVector::<f64, N>::zeros();
    for ((fi, link), &w) in f.iter_mut().zip(model.links.iter()).zip(qd.iter()) {
        *fi = link.damping * w + link.frictionloss * sign(w);
    }
    f
}

/// Planar spatial motion cross product `v x m` for vectors `[angular; x; y]`.
#[inline(always)]
fn cross_motion(v: &Vector3<f64>, m: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(0.0, v.z * m.x - v.x * m.z, v.x * m.y - v.y * m.x)
}

/// Planar spatial force cross product `v x* f` for vectors `[angular; x; y]`.
#[inline(always)]
fn cross_force(v: &Vector3<f64>, f: &Vector3<f64>) -> Vector3<f64> {
    Vector3::new(v.y * f.z - v.z * f.y, -v.x * f.z, v.x * f.y)
}

/// The planar spatial inertia about the world origin of a body of mass `m`, rotational inertia
/// `inertia` about its centre of mass, with the centre of mass at `c`.
#[inline(always)]
fn spatial_inertia(m: f64, inertia: f64, c: Vector2<f64>) -> Matrix3<f64> {
    let mx = m * c.x;
    let my = m * c.y;
    Matrix3::new(
        inertia + mx * c.x + my * c.y,
        -my,
        mx,
        -my,
        m,
        0.0,
        mx,
        0.0,
        m,
    )
}

/// Joint accelerations `qdd` that solve `M qdd = tau - c - g - f` by the articulated body
/// algorithm.
///
/// O(N), and never forms the mass matrix. This is Featherstone's ABA specialised to the plane:
/// spatial vectors are `[angular; x; y]` with 3x3 spatial inertias, all expressed in the world
/// frame about the origin, so that the joint axes are `S_i = [1, y_i, -x_i]` (with `(x_i, y_i)`
/// the joint position) and no coordinate transforms are needed between links. Three passes:
/// velocities and velocity-product terms outwards, articulated inertias and bias forces
/// inwards, accelerations outwards (gravity as an upward base acceleration). The payload's
/// spatial inertia is added to the last link's; the armature enters the joint-space
/// articulated inertia `D_i = S_i^T I^A_i S_i + armature_i`, the friction the joint's torque.
///
/// The result is meaningless (non-finite) if the arm has a degenerate articulated inertia, e.g.
/// a massless, inertialess last link without armature or payload.
#[must_use]
pub fn forward_dynamics<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
    let links = &model.links;
    let dirs = link_directions(q);

    // Pass 1 (outwards): joint axes, velocities, velocity-product accelerations, rigid-body
    // inertias and bias forces.
    let mut axis = [Vector3::zeros(); N];
    let mut c = [Vector3::zeros(); N];
    let mut inertia = [Matrix3::zeros(); N];
    let mut bias = [Vector3::zeros(); N];
    let mut joint = Vector2::zeros();
    let mut v = Vector3::zeros();
    for i in 0..N {
        let link = &links[i];
        let s = Vector3::new(1.0, joint.y, -joint.x);
        let vj = s * qd[i];
        v += vj;
        c[i] = cross_motion(&v, &vj);
        let ii = spatial_inertia(link.mass, link.inertia, joint + in_world(dirs[i], link.com));
        bias[i] = cross_force(&v, &(ii * v));
        inertia[i] = ii;
        axis[i] = s;
        joint += dirs[i] * link.length;
    }
    // The payload moves with the last link (`joint` is the tip, `v` the last link's velocity).
    if let (Some(last_inertia), Some(last_bias)) = (inertia.last_mut(), bias.last_mut()) {
        let payload = &model.payload;
        let centre = joint + in_world(last_direction(&dirs), payload.com);
        let ip = spatial_inertia(payload.mass, payload.inertia, centre);
        *last_inertia += ip;
        *last_bias += cross_force(&v, &(ip * v));
    }

    // Pass 2 (inwards): articulated-body inertias and bias forces.
    let f = friction(model, qd);
    let mut u_vec = [Vector3::zeros(); N];
    let mut d_inv = [0.0; N];
    let mut u_sc = [0.0; N];
    for i in (0..N).rev() {
        let s = axis[i];
        let u = inertia[i] * s;
        let di = 1.0 / (s.dot(&u) + links[i].armature);
        let ui = tau[i] - f[i] - s.dot(&bias[i]);
        if i > 0 {
            let ia = inertia[i] - (u * u.transpose()) * di;
            let pa = bias[i] + ia * c[i] + u * (ui * di);
            inertia[i - 1] += ia;
            bias[i - 1] += pa;
        }
        u_vec[i] = u;
        d_inv[i] = di;
        u_sc[i] = ui;
    }

    // Pass 3 (outwards): accelerations.
    let mut qdd = SVector::zeros();
    let mut a = Vector3::new(0.0, 0.0, model.gravity);
    for i in 0..N {
        a += c[i];
        let qddi = (u_sc[i] - u_vec[i].dot(&a)) * d_inv[i];
        a += axis[i] * qddi;
        qdd[i] = qddi;
    }
    qdd
}

/// Joint accelerations `qdd = M^-1 (tau - c - g - f)` by CRBA, RNEA and a Cholesky solve.
///
/// O(N^3); provided to cross-check and benchmark against [`forward_dynamics`]. If the mass
/// matrix is not positive definite (only possible with degenerate links, e.g. a massless,
/// inertialess last link without armature or payload) every entry is NaN.
#[must_use]
pub fn forward_dynamics_crba<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
    let dirs = link_directions(q);
    let m = crba_dirs(model, &dirs);
    let rhs =
        tau - rnea_dirs(model, model.gravity, &dirs, qd, &SVector::zeros()) - friction(model, qd);
    match m.cholesky() {
        Some(cholesky) => cholesky.solve(&rhs),
        None => SVector::repeat(f64::NAN),
    }
}

/// The kinetic energy, J: `sum(m_i |v_com_i|^2 + inertia_i omega_i^2 + armature_i qd_i^2) / 2`
/// over the links, plus the payload's `(m |v_com|^2 + inertia omega_N^2) / 2`, from the
/// centre-of-mass velocities (`omega_i` the absolute rate of link i, `qd_i` its joint's own).
#[inline]
#[must_use]
pub fn kinetic_energy<const N: usize>(
    model: &Model<N>,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    let dirs = link_directions(q);
    let mut v_joint = Vector2::zeros();
    let mut omega = 0.0;
    let mut energy = 0.0;
    for i in 0..N {
        let link = &model.links[i];
        let u = dirs[i];
        omega += qd[i];
        let v_com = v_joint + perp(in_world(u, link.com)) * omega;
        energy += link.mass * v_com.norm_squared()
            + link.inertia * omega * omega
            + link.armature * qd[i] * qd[i];
        v_joint += perp(u) * (omega * link.length);
    }
    let payload = &model.payload;
    let v_payload = v_joint + perp(in_world(last_direction(&dirs), payload.com)) * omega;
    energy += payload.mass * v_payload.norm_squared() + payload.inertia * omega * omega;
    0.5 * energy
}

/// The gravitational potential energy `gravity * (sum(m_i y_com_i) + m_payload y_payload)`, J,
/// zero at the base height.
#[inline]
#[must_use]
pub fn potential_energy<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> f64 {
    let dirs = link_directions(q);
    let mut y_joint = 0.0;
    let mut moment = 0.0;
    for (link, &dir) in model.links.iter().zip(dirs.iter()) {
        moment += link.mass * (y_joint + in_world(dir, link.com).y);
        y_joint += link.length * dir.y;
    }
    let payload = &model.payload;
    moment += payload.mass * (y_joint + in_world(last_direction(&dirs), payload.com).y);
    model.gravity * moment
}

/// The position of the tip (the far end of the last link), m.
#[inline]
#[must_use]
pub fn tip_position<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> Point2<f64> {
    let dirs = link_directions(q);
    let mut tip = Point2::origin();
    for (link, dir) in model.links.iter().zip(dirs.iter()) {
        tip += dir * link.length;
    }
    tip
}

/// The absolute angle of the last link from +x, `q[0] + ... + q[N-1]` (not wrapped), rad.
#[inline]
#[must_use]
pub fn tip_angle<const N: usize>(q: &SVector<f64, N>) -> f64 {
    q.sum()
}

/// The positions of joints 1..=N, m; joint 1 is at the origin.
#[inline]
#[must_use]
pub fn joint_positions<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> [Point2<f64>; N] {
    let dirs = link_directions(q);
    let mut joints = [Point2::origin(); N];
    let mut p = Point2::origin();
    for ((joint, link), dir) in joints.iter_mut().zip(model.links.iter()).zip(dirs.iter()) {
        *joint = p;
        p += dir * link.length;
    }
    joints
}

/// The 3 x N tip Jacobian: rows are the rates of the tip's x, the tip's y and the last link's
/// absolute angle with respect to `qd`.
///
/// Column j is `[perp(tip - joint_j); 1]`, since joint j rotates everything beyond it.
#[inline]
#[must_use]
pub fn jacobian<const N: usize>(model: &Model<N>, q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
    let dirs = link_directions(q);
    let mut jac = SMatrix::<f64, 3, N>::zeros();
    // Walk inwards accumulating the vector from joint j to the tip.
    let mut r = Vector2::zeros();
    for j in (0..N).rev() {
        r += dirs[j] * model.links[j].length;
        jac[(0, j)] = -r.y;
        jac[(1, j)] = r.x;
        jac[(2, j)] = 1.0;
    }
    jac
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Link, Payload};
    use nalgebra::{Matrix2, Vector2 as V2};

    /// SplitMix64: a tiny deterministic PRNG.
    struct Rng(u64);

    impl Rng {
        fn next_u64(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^ (z >> 31)
        }

        /// Uniform in `[lo, hi)`.
        fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
            #[allow(clippy::cast_precision_loss)]
            let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
            lo + (hi - lo) * unit
        }

        /// `value()` with probability 3/4, else zero: the zero special case stays covered.
        fn often(&mut self, value: impl FnOnce(&mut Self) -> f64) -> f64 {
            if self.uniform(0.0, 1.0) < 0.75 {
                value(self)
            } else {
                0.0
            }
        }

        fn links<const N: usize>(&mut self) -> [Link; N] {
            core::array::from_fn(|_| {
                let length = self.uniform(0.2, 2.0);
                let mass = self.uniform(0.1, 5.0);
                Link {
                    length,
                    mass,
                    inertia: mass * length * length * self.uniform(0.01, 0.2),
                    // Anywhere along the link, sometimes a little beyond either end, and off
                    // the link's axis to either side.
                    com: V2::new(
                        length * self.uniform(-0.2, 1.2),
                        length * self.uniform(-0.3, 0.3),
                    ),
                    armature: self.often(|r| r.uniform(0.0, 0.5)),
                    damping: self.often(|r| r.uniform(0.0, 2.0)),
                    frictionloss: self.often(|r| r.uniform(0.0, 1.0)),
                    joint: crate::Joint::Revolute,
                    range: None,
                }
            })
        }

        fn payload(&mut self) -> Payload {
            if self.uniform(0.0, 1.0) < 0.25 {
                return Payload::NONE;
            }
            Payload {
                mass: self.uniform(0.0, 3.0),
                inertia: self.uniform(0.0, 0.2),
                com: V2::new(self.uniform(-0.3, 0.3), self.uniform(-0.3, 0.3)),
            }
        }

        fn model<const N: usize>(&mut self) -> Model<N> {
            let gravity = self.uniform(0.0, 15.0);
            Model::new(self.links(), gravity).with_payload(self.payload())
        }

        fn vector<const N: usize>(&mut self, bound: f64) -> SVector<f64, N> {
            SVector::from_fn(|_, _| self.uniform(-bound, bound))
        }
    }

    /// `|a - b| <= tol * max(1, |a|, |b|)` element-wise, on the max-norm scale of the operands.
    #[track_caller]
    fn assert_close<const R: usize, const C: usize>(
        a: &SMatrix<f64, R, C>,
        b: &SMatrix<f64, R, C>,
        tol: f64,
        what: &str,
    ) {
        let scale = 1.0_f64.max(a.amax()).max(b.amax());
        let err = (a - b).amax();
        assert!(
            err <= tol * scale,
            "{what}: error {err:e} exceeds {tol:e} * {scale}\n  a = {a}\n  b = {b}"
        );
    }

    #[track_caller]
    fn assert_close_f(a: f64, b: f64, tol: f64, what: &str) {
        let scale = 1.0_f64.max(a.abs()).max(b.abs());
        assert!(
            (a - b).abs() <= tol * scale,
            "{what}: {a} vs {b} (error {:e})",
            (a - b).abs()
        );
    }

    /// `value` times the j-th standard basis vector.
    fn basis<const N: usize>(j: usize, value: f64) -> SVector<f64, N> {
        SVector::from_fn(|i, _| if i == j { value } else { 0.0 })
    }

    #[test]
    fn pendulum_by_hand() {
        let link = Link {
            length: 1.3,
            mass: 2.1,
            inertia: 0.37,
            com: V2::new(0.55, -0.2),
            armature: 0.05,
            damping: 0.3,
            frictionloss: 0.4,
            joint: crate::Joint::Revolute,
            range: None,
        };
        let model = Model::new([link], 9.81);
        let (cx, cy) = (0.55, -0.2);
        let mut rng = Rng(1);
        for _ in 0..50 {
            let q = rng.uniform(-4.0, 4.0);
            let qd = rng.uniform(-5.0, 5.0);
            let qdd = rng.uniform(-5.0, 5.0);
            // Joint inertia by the parallel-axis theorem, plus the armature; the centre of mass
            // is at angle q + atan2(cy, cx), so its height is cx sin q + cy cos q and the
            // gravity torque m g (cx cos q - cy sin q).
            let inertia = 0.37 + 2.1 * (cx * cx + cy * cy) + 0.05;
            let gravity = 2.1 * 9.81 * (cx * q.cos() - cy * q.sin());
            let friction = 0.3 * qd + 0.4 * qd.signum();
            let expected = inertia * qdd + gravity + friction;
            let (q, qd, qdd) = (
                SVector::from([q]),
                SVector::from([qd]),
                SVector::from([qdd]),
            );
            assert_close_f(
                inverse_dynamics(&model, &q, &qd, &qdd)[0],
                expected,
                1e-13,
                "pendulum tau",
            );
            assert_close_f(mass_matrix(&model, &q)[(0, 0)], inertia, 1e-15, "M");
            assert_close_f(gravity_torques(&model, &q)[0], gravity, 1e-13, "g");
            assert_close_f(coriolis(&model, &q, &qd)[0], 0.0, 1e-13, "c");
            assert_close_f(
                potential_energy(&model, &q),
                2.1 * 9.81 * (cx * q[0].sin() + cy * q[0].cos()),
                1e-13,
                "V",
            );
        }
    }

    /// The textbook closed form of the general two-link arm, with the centres of mass off the
    /// links' axes (`c2 = (a, b)` in link 2's frame), armature and friction.
    fn two_link_closed_form(
        model: &Model<2>,
        q: &V2<f64>,
        qd: &V2<f64>,
    ) -> (Matrix2<f64>, V2<f64>, V2<f64>, V2<f64>) {
        let [l1, l2] = model.links;
        let (m1, m2, len1, c1, c2) = (l1.mass, l2.mass, l1.length, l1.com, l2.com);
        let (a, b) = (c2.x, c2.y);
        let g = model.gravity;
        let (s2, cos2) = q[1].sin_cos();
        // Link 2's centre seen from joint 1 is `len1 e_x + R(q2) c2`: its dot product with
        // `len1 e_x` is `len1 (a cos q2 - b sin q2)`.
        let p = len1 * (a * cos2 - b * s2);
        let m22 = l2.inertia + m2 * c2.norm_squared();
        let m11 = l1.inertia + m1 * c1.norm_squared() + m22 + m2 * (len1 * len1 + 2.0 * p);
        let m12 = m22 + m2 * p;
        // h = -dM12/dq2 = m2 len1 (a sin q2 + b cos q2).
        let h = m2 * len1 * (a * s2 + b * cos2);
        let c = V2::new(
            -h * qd[1] * qd[1] - 2.0 * h * qd[0] * qd[1],
            h * qd[0] * qd[0],
        );
        let (s1, cos1) = q[0].sin_cos();
        let (s12, cos12) = (q[0] + q[1]).sin_cos();
        let grav2 = g * m2 * (a * cos12 - b * s12);
        let grav = V2::new(
            g * m1 * (c1.x * cos1 - c1.y * s1) + g * m2 * len1 * cos1 + grav2,
            grav2,
        );
        let sign = |x: f64| if x == 0.0 { 0.0 } else { x.signum() };
        let f = V2::new(
            l1.damping * qd[0] + l1.frictionloss * sign(qd[0]),
            l2.damping * qd[1] + l2.frictionloss * sign(qd[1]),
        );
        let m = Matrix2::new(m11 + l1.armature, m12, m12, m22 + l2.armature);
        (m, c, grav, f)
    }

    #[test]
    fn two_link_matches_closed_form() {
        let mut rng = Rng(2);
        for _ in 0..200 {
            let model = Model::new(rng.links::<2>(), rng.uniform(0.0, 15.0));
            let q = rng.vector::<2>(4.0);
            let qd = rng.vector::<2>(5.0);
            let qdd = rng.vector::<2>(5.0);
            let (m, c, grav, f) = two_link_closed_form(&model, &q, &qd);
            assert_close(&mass_matrix(&model, &q), &m, 1e-13, "M");
            assert_close(&coriolis(&model, &q, &qd), &c, 1e-13, "c");
            assert_close(&gravity_torques(&model, &q), &grav, 1e-13, "g");
            assert_close(&friction(&model, &qd), &f, 1e-15, "f");
            assert_close(
                &bias_forces(&model, &q, &qd),
                &(c + grav + f),
                1e-13,
                "c + g + f",
            );
            assert_close(
                &inverse_dynamics(&model, &q, &qd, &qdd),
                &(m * qdd + c + grav + f),
                1e-13,
                "tau",
            );
        }
    }

    #[test]
    fn paper_equal_rods_mass_matrix() {
        let model = Model::new([Link::rod(1.0, 1.0); 2], 9.81);
        for q2 in [0.0_f64, 0.4, 1.0, -2.5, 3.0] {
            let q = SVector::from([0.7, q2]);
            let c = q2.cos();
            let expected = Matrix2::new(
                5.0 / 3.0 + c,
                1.0 / 3.0 + c / 2.0,
                1.0 / 3.0 + c / 2.0,
                1.0 / 3.0,
            );
            assert_close(&mass_matrix(&model, &q), &expected, 1e-15, "paper M");
        }
    }

    /// All the cross-checks between algorithms for one random arm and state.
    fn cross_check<const N: usize>(rng: &mut Rng) {
        let model: Model<N> = rng.model();
        let q = rng.vector::<N>(std::f64::consts::PI);
        let qd = rng.vector::<N>(3.0);
        let tau = rng.vector::<N>(20.0);
        let zero = SVector::<f64, N>::zeros();
        let tol = 1e-10;

        // CRBA against columns of RNEA(qd = 0, g = 0, qdd = e_j); friction vanishes at rest.
        let m = mass_matrix(&model, &q);
        let weightless = Model {
            gravity: 0.0,
            ..model
        };
        let m_rnea = SMatrix::<f64, N, N>::from_fn(|i, j| {
            inverse_dynamics(&weightless, &q, &zero, &basis(j, 1.0))[i]
        });
        assert_close(&m, &m_rnea, tol, "CRBA vs RNEA columns");
        assert_close(&m, &m.transpose(), 0.0, "M symmetric");

        // Bias decomposition.
        let bias = bias_forces(&model, &q, &qd);
        let grav = gravity_torques(&model, &q);
        let cor = coriolis(&model, &q, &qd);
        let fric = friction(&model, &qd);
        assert_close(&bias, &(cor + grav + fric), tol, "bias = c + g + f");
        assert_close(
            &grav,
            &inverse_dynamics(&model, &q, &zero, &zero),
            tol,
            "g vs RNEA",
        );
        assert_close(
            &inverse_dynamics_batched_trig(&model, &q, &qd, &tau),
            &inverse_dynamics(&model, &q, &qd, &tau),
            tol,
            "batched trigonometry",
        );

        // ABA against CRBA + Cholesky, and round trip through inverse dynamics.
        let qdd_aba = forward_dynamics(&model, &q, &qd, &tau);
        let qdd_crba = forward_dynamics_crba(&model, &q, &qd, &tau);
        assert_close(&qdd_aba, &qdd_crba, tol, "ABA vs CRBA");
        assert_close(
            &inverse_dynamics(&model, &q, &qd, &qdd_aba),
            &tau,
            tol,
            "RNEA(ABA(tau))",
        );
        assert_close(&(m * qdd_aba + bias), &tau, tol, "M qdd + bias = tau");

        // Kinetic energy against the mass matrix, both ways: T = qd' M qd / 2, and M is the
        // Hessian of T in qd. T is exactly quadratic in qd, so central second differences
        // with a unit step have no truncation error, only rounding.
        let t = |v: &SVector<f64, N>| kinetic_energy(&model, &q, v);
        assert_close_f(t(&qd), 0.5 * qd.dot(&(m * qd)), tol, "T = qd' M qd / 2");
        let hessian = SMatrix::<f64, N, N>::from_fn(|i, j| {
            let (ei, ej) = (basis::<N>(i, 1.0), basis::<N>(j, 1.0));
            (t(&(qd + ei + ej)) - t(&(qd + ei - ej)) - t(&(qd - ei + ej)) + t(&(qd - ei - ej)))
                / 4.0
        });
        assert_close(&m, &hessian, tol, "M = d2T/dqd2");

        // Gravity torques, RNEA at rest and Jacobian against central finite differences of
        // the potential energy and the tip.
        let h = 1e-6;
        let fd_tol = 1e-7;
        let at_rest = inverse_dynamics(&model, &q, &zero, &zero);
        let mut jac_fd = SMatrix::<f64, 3, N>::zeros();
        for j in 0..N {
            let dq = basis::<N>(j, h);
            let (qp, qm) = (q + dq, q - dq);
            let dv = (potential_energy(&model, &qp) - potential_energy(&model, &qm)) / (2.0 * h);
            assert_close_f(grav[j], dv, fd_tol, "g = dV/dq");
            assert_close_f(at_rest[j], dv, fd_tol, "RNEA(qd = qdd = 0) = dV/dq");
            let dp = (tip_position(&model, &qp) - tip_position(&model, &qm)) / (2.0 * h);
            let da = (tip_angle(&qp) - tip_angle(&qm)) / (2.0 * h);
            jac_fd.set_column(j, &Vector3::new(dp.x, dp.y, da));
        }
        assert_close(&jacobian(&model, &q), &jac_fd, fd_tol, "Jacobian");

        // The payload handled inside each algorithm against the payload merged into the last
        // link by the parallel-axis theorem.
        let merged = Model::new(model.rigid_links(), model.gravity);
        let qdd = rng.vector::<N>(5.0);
        assert_close(&mass_matrix(&merged, &q), &m, tol, "merged M");
        assert_close(
            &inverse_dynamics(&merged, &q, &qd, &qdd),
            &inverse_dynamics(&model, &q, &qd, &qdd),
            tol,
            "merged tau",
        );
        assert_close(&gravity_torques(&merged, &q), &grav, tol, "merged g");
        assert_close(&coriolis(&merged, &q, &qd), &cor, tol, "merged c");
        assert_close(
            &forward_dynamics(&merged, &q, &qd, &tau),
            &qdd_aba,
            tol,
            "merged ABA",
        );
        assert_close_f(kinetic_energy(&merged, &q, &qd), t(&qd), tol, "merged T");
        assert_close_f(
            potential_energy(&merged, &q),
            potential_energy(&model, &q),
            tol,
            "merged V",
        );

        // Joint 1 at the origin; the last link runs from the last joint to the tip along the
        // tip angle.
        let joints = joint_positions(&model, &q);
        assert_eq!(joints[0], Point2::origin());
        let last_link = tip_position(&model, &q) - joints[N - 1];
        let (s, c) = tip_angle(&q).sin_cos();
        assert_close(
            &last_link,
            &(V2::new(c, s) * model.links[N - 1].length),
            1e-12,
            "last link",
        );
    }

    #[test]
    fn cross_checks_n1_to_n8() {
        let mut rng = Rng(3);
        for _ in 0..200 {
            cross_check::<1>(&mut rng);
            cross_check::<2>(&mut rng);
            cross_check::<3>(&mut rng);
            cross_check::<4>(&mut rng);
            cross_check::<5>(&mut rng);
            cross_check::<6>(&mut rng);
            cross_check::<7>(&mut rng);
            cross_check::<8>(&mut rng);
        }
    }

    /// Armature is a constant on M's diagonal: exactly `A_i` added there and nowhere else,
    /// `A_i qdd_i` added to the torque, `A_i qd_i^2 / 2` to the kinetic energy.
    fn armature_check<const N: usize>(rng: &mut Rng) {
        let model: Model<N> = rng.model();
        let bare = Model {
            links: model.links.map(|l| l.with_armature(0.0)),
            ..model
        };
        let q = rng.vector::<N>(4.0);
        let qd = rng.vector::<N>(3.0);
        let qdd = rng.vector::<N>(5.0);
        let (m, m_bare) = (mass_matrix(&model, &q), mass_matrix(&bare, &q));
        let armature = SVector::<f64, N>::from_fn(|i, _| model.links[i].armature);
        for i in 0..N {
            for j in 0..N {
                let expected = if i == j {
                    m_bare[(i, j)] + armature[i]
                } else {
                    m_bare[(i, j)]
                };
                assert_eq!(m[(i, j)], expected, "M[{i}][{j}]");
            }
        }
        assert_close(
            &(inverse_dynamics(&model, &q, &qd, &qdd) - inverse_dynamics(&bare, &q, &qd, &qdd)),
            &armature.component_mul(&qdd),
            1e-12,
            "armature torque",
        );
        assert_close(
            &(coriolis(&model, &q, &qd) - coriolis(&bare, &q, &qd)),
            &SVector::zeros(),
            0.0,
            "armature leaves c alone",
        );
        assert_close_f(
            kinetic_energy(&model, &q, &qd) - kinetic_energy(&bare, &q, &qd),
            0.5 * armature.dot(&qd.component_mul(&qd)),
            1e-12,
            "armature energy",
        );
    }

    #[test]
    fn armature_is_on_the_diagonal_only() {
        let mut rng = Rng(4);
        for _ in 0..50 {
            armature_check::<1>(&mut rng);
            armature_check::<3>(&mut rng);
            armature_check::<6>(&mut rng);
        }
    }

    /// A payload against the last link with mass, centre of mass and inertia combined by
    /// hand. The rod: 1 m, 2 kg, centre (0.5, 0), inertia 2/12 = 1/6. The payload: 1 kg,
    /// inertia 0.05, centre 0.5 beyond the tip and 0.3 to the left, i.e. at (1.5, 0.3) in the
    /// link's frame. Together: 3 kg with centre ((2 * 0.5 + 1.5) / 3, 0.3 / 3) = (5/6, 0.1);
    /// about it the rod adds 1/6 + 2 ((1/3)^2 + 0.1^2) = 1/6 + 2/9 + 0.02 and the payload
    /// 0.05 + 1 ((2/3)^2 + 0.2^2) = 0.05 + 4/9 + 0.04, in all 5/6 + 0.11. (Check: about the
    /// joint, 2/3 + 2.39 = 3.0566... = 5/6 + 0.11 + 3 (25/36 + 0.01).)
    #[test]
    fn payload_is_a_heavier_last_link() {
        let upper = Link::rod(0.8, 1.5).with_com(0.3, 0.05).with_armature(0.02);
        let fore = Link::rod(1.0, 2.0).with_damping(0.1);
        let payload = Payload::point(1.0).with_inertia(0.05).with_com(0.5, 0.3);
        let held = Model::new([upper, fore], 9.81).with_payload(payload);
        let by_hand = Model::new(
            [
                upper,
                Link {
                    mass: 3.0,
                    com: V2::new(5.0 / 6.0, 0.1),
                    inertia: 5.0 / 6.0 + 0.11,
                    ..fore
                },
            ],
            9.81,
        );
        let merged = held.rigid_links();
        assert_eq!(merged[0], upper);
        assert_close_f(merged[1].mass, 3.0, 1e-15, "mass");
        assert_close(&merged[1].com, &V2::new(5.0 / 6.0, 0.1), 1e-15, "com");
        assert_close_f(merged[1].inertia, 5.0 / 6.0 + 0.11, 1e-15, "inertia");
        assert_close_f(
            merged[1].inertia_about_joint(),
            2.0 / 3.0 + 2.39,
            1e-15,
            "inertia about the joint",
        );
        assert_eq!(
            (merged[1].length, merged[1].damping),
            (1.0, 0.1),
            "joint parameters kept"
        );

        let mut rng = Rng(5);
        for _ in 0..50 {
            let q = rng.vector::<2>(4.0);
            let qd = rng.vector::<2>(3.0);
            let qdd = rng.vector::<2>(5.0);
            let tol = 1e-13;
            assert_close(
                &mass_matrix(&held, &q),
                &mass_matrix(&by_hand, &q),
                tol,
                "M",
            );
            assert_close(
                &coriolis(&held, &q, &qd),
                &coriolis(&by_hand, &q, &qd),
                tol,
                "c",
            );
            assert_close(
                &gravity_torques(&held, &q),
                &gravity_torques(&by_hand, &q),
                tol,
                "g",
            );
            assert_close(
                &inverse_dynamics(&held, &q, &qd, &qdd),
                &inverse_dynamics(&by_hand, &q, &qd, &qdd),
                tol,
                "tau",
            );
            assert_close(
                &forward_dynamics(&held, &q, &qd, &qdd),
                &forward_dynamics(&by_hand, &q, &qd, &qdd),
                1e-12,
                "ABA",
            );
            assert_close_f(
                kinetic_energy(&held, &q, &qd),
                kinetic_energy(&by_hand, &q, &qd),
                tol,
                "T",
            );
            assert_close_f(
                potential_energy(&held, &q),
                potential_energy(&by_hand, &q),
                tol,
                "V",
            );
        }
        // The tip is the end of the last link, payload or not.
        let q = SVector::from([0.4, -1.0]);
        assert_eq!(tip_position(&held, &q), tip_position(&by_hand, &q));
    }

    #[test]
    fn massless_payload_merges_its_inertia_only() {
        let link = Link::rod(1.0, 0.0).with_inertia(0.0);
        let held = Model::new([link], 0.0).with_payload(Payload::NONE.with_inertia(0.25));
        let [merged] = held.rigid_links();
        assert_eq!(
            (merged.mass, merged.inertia, merged.com),
            (0.0, 0.25, link.com)
        );
        assert_eq!(Model::new([link], 0.0).rigid_links(), [link]);
    }

    #[test]
    fn friction_law() {
        let links = [
            Link::rod(1.0, 1.0).with_damping(0.5).with_frictionloss(0.2),
            Link::rod(1.0, 1.0).with_damping(0.5),
            Link::rod(1.0, 1.0).with_frictionloss(0.2),
        ];
        let model = Model::new(links, 9.81);
        // sign(0) = sign(-0) = 0: no Coulomb friction at rest, whichever zero.
        for zero in [0.0, -0.0] {
            let f = friction(&model, &SVector::from([zero; 3]));
            assert_eq!(f, SVector::<f64, 3>::zeros());
        }
        let f = friction(&model, &SVector::from([-2.0, 3.0, 1e-300]));
        assert_eq!(f, SVector::from([-1.0 - 0.2, 1.5, 0.2]));
        // The viscous part is linear in qd; the Coulomb part depends on its sign alone.
        let viscous = Model::new(links.map(|l| l.with_frictionloss(0.0)), 9.81);
        let mut rng = Rng(6);
        for _ in 0..50 {
            let (a, b) = (rng.vector::<3>(5.0), rng.vector::<3>(5.0));
            let k = rng.uniform(-3.0, 3.0);
            assert_close(
                &friction(&viscous, &(a * k + b)),
                &(friction(&viscous, &a) * k + friction(&viscous, &b)),
                1e-14,
                "damping is linear",
            );
            let coulomb = |v: &SVector<f64, 3>| friction(&model, v) - friction(&viscous, v);
            assert_close(
                &coulomb(&(a * 7.0)),
                &coulomb(&a),
                1e-13,
                "Coulomb depends on the sign alone",
            );
        }
        // NaN in gives NaN out, also through a frictionless joint.
        let f = friction(&model, &SVector::from([f64::NAN; 3]));
        assert!(f.iter().all(|x| x.is_nan()), "{f}");
    }

    /// Power balance along a trajectory: `d/dt (T + V) = qd . (tau - f)`. Integrates
    /// `qdd = ABA(q, qd, tau)` by classical RK4 from `(q, qd)` and returns the energy change,
    /// the work done on the arm by `tau - f` (Simpson's rule on the same grid) and the largest
    /// difference between the energy's rate (central differences) and the power, each
    /// relative to the energy scale of the run.
    fn power_balance<const N: usize>(
        model: &Model<N>,
        tau: &SVector<f64, N>,
        mut q: SVector<f64, N>,
        mut qd: SVector<f64, N>,
    ) -> (f64, f64, f64) {
        let energy = |q: &SVector<f64, N>, qd: &SVector<f64, N>| {
            kinetic_energy(model, q, qd) + potential_energy(model, q)
        };
        let power = |qd: &SVector<f64, N>| qd.dot(&(tau - friction(model, qd)));
        let accel = |q: &SVector<f64, N>, qd: &SVector<f64, N>| forward_dynamics(model, q, qd, tau);
        let (dt, steps) = (2.5e-4, 800);
        let (mut energies, mut powers) = (vec![energy(&q, &qd)], vec![power(&qd)]);
        for _ in 0..steps {
            let k1 = (qd, accel(&q, &qd));
            let (q2, v2) = (q + k1.0 * (dt / 2.0), qd + k1.1 * (dt / 2.0));
            let k2 = (v2, accel(&q2, &v2));
            let (q3, v3) = (q + k2.0 * (dt / 2.0), qd + k2.1 * (dt / 2.0));
            let k3 = (v3, accel(&q3, &v3));
            let (q4, v4) = (q + k3.0 * dt, qd + k3.1 * dt);
            let k4 = (v4, accel(&q4, &v4));
            q += (k1.0 + k2.0 * 2.0 + k3.0 * 2.0 + k4.0) * (dt / 6.0);
            qd += (k1.1 + k2.1 * 2.0 + k3.1 * 2.0 + k4.1) * (dt / 6.0);
            energies.push(energy(&q, &qd));
            powers.push(power(&qd));
        }
        let work: f64 = powers
            .iter()
            .enumerate()
            .map(|(k, p)| {
                let weight = if k == 0 || k == steps {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                weight * p
            })
            .sum::<f64>()
            * (dt / 3.0);
        // Fourth-order central differences: truncation O(dt^4), like the integrator's.
        let rate_error = (2..steps - 1)
            .map(|k| {
                let rate = (energies[k - 2] - 8.0 * energies[k - 1] + 8.0 * energies[k + 1]
                    - energies[k + 2])
                    / (12.0 * dt);
                (rate - powers[k]).abs()
            })
            .fold(0.0, f64::max);
        let scale = energies
            .iter()
            .chain(powers.iter())
            .fold(1.0_f64, |m, e| m.max(e.abs()));
        (
            (energies[steps] - energies[0]) / scale,
            work / scale,
            rate_error / scale,
        )
    }

    fn power_balance_check<const N: usize>(rng: &mut Rng) {
        let mut model: Model<N> = rng.model();
        for link in &mut model.links {
            // Coulomb friction switches at qd_i = 0, which RK4 does not resolve; the law is
            // checked on its own in `friction_law`.
            link.frictionloss = 0.0;
            link.damping = rng.uniform(0.1, 2.0);
        }
        let (q, qd) = (rng.vector::<N>(3.0), rng.vector::<N>(2.0));

        // Unforced: the energy only decreases, by exactly the damping's dissipation.
        let (change, work, rate) = power_balance(&model, &SVector::zeros(), q, qd);
        assert!(change < 0.0, "a damped free arm loses energy: {change}");
        assert!(
            (change - work).abs() < 1e-10 && rate < 1e-8,
            "N = {N}: dE {change:e} vs -sum B qd^2 dt {work:e}; rate error {rate:e}"
        );
        // Driven: the motors' work less the dissipation.
        let tau = rng.vector::<N>(10.0);
        let (change, work, rate) = power_balance(&model, &tau, q, qd);
        assert!(
            (change - work).abs() < 1e-10 && rate < 1e-8,
            "N = {N}: dE {change:e} vs work {work:e}; rate error {rate:e}"
        );
    }

    #[test]
    fn power_balance_along_trajectories() {
        let mut rng = Rng(7);
        for _ in 0..5 {
            power_balance_check::<1>(&mut rng);
            power_balance_check::<2>(&mut rng);
            power_balance_check::<3>(&mut rng);
            power_balance_check::<5>(&mut rng);
        }
    }

    #[test]
    fn kinematics_by_hand() {
        let model = Model::new(
            [
                Link::rod(1.0, 1.0),
                Link::rod(2.0, 1.0),
                Link::rod(0.5, 1.0),
            ],
            9.81,
        );
        let q = SVector::from([
            std::f64::consts::FRAC_PI_2,
            -std::f64::consts::FRAC_PI_2,
            0.0,
        ]);
        let joints = joint_positions(&model, &q);
        assert_close(&joints[1].coords, &V2::new(0.0, 1.0), 1e-15, "joint 2");
        assert_close(&joints[2].coords, &V2::new(2.0, 1.0), 1e-15, "joint 3");
        assert_close(
            &tip_position(&model, &q).coords,
            &V2::new(2.5, 1.0),
            1e-15,
            "tip",
        );
        assert_close_f(tip_angle(&q), 0.0, 0.0, "tip angle");
        // Joint 3 rotates only the last link: tip velocity perp((0.5, 0)) = (0, 0.5).
        let jac = jacobian(&model, &q);
        assert_close(
            &jac.column(2).into_owned(),
            &Vector3::new(0.0, 0.5, 1.0),
            1e-15,
            "J col 3",
        );
        assert_close(
            &jac.column(0).into_owned(),
            &Vector3::new(-1.0, 2.5, 1.0),
            1e-15,
            "J col 1",
        );
    }

    #[test]
    fn energies_by_hand() {
        // A single rod spinning about its joint at rate w, held horizontal then raised.
        let rod = Model::new([Link::rod(2.0, 3.0)], 9.81);
        let w = 1.5;
        let joint_inertia = 3.0 * 4.0 / 3.0;
        let (flat, up) = (
            SVector::from([0.3]),
            SVector::from([std::f64::consts::FRAC_PI_2]),
        );
        assert_close_f(
            kinetic_energy(&rod, &flat, &SVector::from([w])),
            0.5 * joint_inertia * w * w,
            1e-15,
            "rod T",
        );
        assert_close_f(potential_energy(&rod, &up), 9.81 * 3.0, 1e-15, "rod V");
        // With a rotor of armature 0.5, a 2 kg point at the tip (2 m from the joint) and the
        // centre of mass moved 1 m to the rod's right: (1, 1) when the rod points up.
        let geared = Model::new(
            [Link::rod(2.0, 3.0).with_com(1.0, -1.0).with_armature(0.5)],
            9.81,
        )
        .with_payload(Payload::point(2.0));
        assert_close_f(
            kinetic_energy(&geared, &flat, &SVector::from([w])),
            0.5 * (1.0 + 3.0 * 2.0 + 0.5 + 2.0 * 4.0) * w * w,
            1e-15,
            "geared T",
        );
        assert_close_f(
            potential_energy(&geared, &up),
            9.81 * (3.0 * (1.0 + 0.0) + 2.0 * 2.0),
            1e-15,
            "geared V",
        );
    }

    #[test]
    fn no_links_no_panic() {
        let model = Model::<0>::new([], 9.81).with_payload(Payload::point(1.0));
        let z = SVector::<f64, 0>::zeros();
        assert_eq!(model.rigid_links(), []);
        assert_eq!(inverse_dynamics(&model, &z, &z, &z).len(), 0);
        assert_eq!(forward_dynamics(&model, &z, &z, &z).len(), 0);
        assert_eq!(forward_dynamics_crba(&model, &z, &z, &z).len(), 0);
        assert_eq!(mass_matrix(&model, &z).len(), 0);
        assert_eq!(gravity_torques(&model, &z).len(), 0);
        assert_eq!(kinetic_energy(&model, &z, &z), 0.0);
        assert_eq!(potential_energy(&model, &z), 0.0);
        assert_eq!(tip_position(&model, &z), Point2::origin());
    }

    #[test]
    fn degenerate_arm_gives_nan_not_a_panic() {
        let massless = Model::new([Link::rod(1.0, 0.0)], 9.81);
        let one = SVector::from([1.0]);
        assert!(forward_dynamics_crba(&massless, &one, &one, &one)[0].is_nan());
        // A rotor alone makes it well posed: qdd = tau / armature.
        let geared = Model::new([Link::rod(1.0, 0.0).with_armature(0.5)], 9.81);
        let rest = SVector::zeros();
        assert_close_f(
            forward_dynamics_crba(&geared, &one, &rest, &one)[0],
            2.0,
            1e-15,
            "CRBA",
        );
        assert_close_f(
            forward_dynamics(&geared, &one, &rest, &one)[0],
            2.0,
            1e-15,
            "ABA",
        );
    }
}
