//! Independent numeric reference implementations of planar-arm dynamics and kinematics.
//!
//! Everything here is plain `f64` arithmetic written from first principles (Newton-Euler
//! mechanics and Featherstone's spatial-vector algorithms specialised to the plane). It shares
//! no code with the symbolic Lagrangian path of `#[derive(PlanarArm)]`, so the tests, the
//! benchmarks and the `paper` example use it as the ground truth the generated code is checked
//! and timed against.
//!
//! Conventions are those of the crate: `q[0]` is link 1's angle from +x and `q[i]` (i > 0) is
//! link i+1's angle relative to link i, so the absolute angle of link i+1 is
//! `phi_i = q[0] + ... + q[i]`; joint 1 sits at the origin; gravity of magnitude `gravity` acts
//! along -y; the equations of motion are `tau = M(q) qdd + c(q, qd) + g(q)`.
//!
//! # Algorithms and cost
//!
//! All functions are generic over the number of links `N`, work on fixed-size arrays and
//! nalgebra `SVector`/`SMatrix` values, never allocate, and evaluate exactly one `sin_cos` per
//! joint (of the cumulative absolute angle).
//!
//! | function | algorithm | cost |
//! |---|---|---|
//! | [`inverse_dynamics`], [`bias_forces`], [`coriolis`] | recursive Newton-Euler (RNEA): outward pass for angular velocity/acceleration and joint/COM linear accelerations (gravity as a base acceleration `+g` along +y), inward pass for joint forces and moments | O(N) |
//! | [`gravity_torques`] | inward accumulation of composite mass and first moment (statics) | O(N) |
//! | [`mass_matrix`] | composite rigid body algorithm (CRBA) with planar composite inertias (mass, first moment, rotational inertia about each joint) | O(N^2) |
//! | [`forward_dynamics`] | articulated body algorithm (ABA) with 3x3 planar spatial inertias `[angular; x; y]`, all expressed about the world origin so that no inter-link transforms are needed; never forms `M` | O(N) |
//! | [`forward_dynamics_crba`] | CRBA + RNEA bias + Cholesky solve | O(N^3) |
//! | [`kinetic_energy`], [`potential_energy`] | direct sums over COM velocities / heights | O(N) |
//! | [`tip_position`], [`joint_positions`], [`jacobian`] | forward kinematics; the Jacobian column of joint j is `perp(tip - joint_j)` | O(N) / O(N) / O(N) |

use nalgebra::{Matrix3, Point2, SMatrix, SVector, Vector2, Vector3};

use crate::Link;

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

/// `a` rotated by +90 degrees.
#[inline(always)]
fn perp(a: Vector2<f64>) -> Vector2<f64> {
    Vector2::new(-a.y, a.x)
}

/// The scalar (z) component of the planar cross product `a x b`.
#[inline(always)]
fn cross(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

/// Recursive Newton-Euler on precomputed link directions.
#[inline(always)]
fn rnea_dirs<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    dirs: &[Vector2<f64>; N],
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    // Outward pass. Gravity is modelled by accelerating the base upwards at `gravity`.
    let mut alpha = [0.0; N];
    let mut a_com = [Vector2::zeros(); N];
    let mut a_joint = Vector2::new(0.0, gravity);
    let mut omega = 0.0;
    let mut omega_dot = 0.0;
    for i in 0..N {
        omega += qd[i];
        omega_dot += qdd[i];
        let u = dirs[i];
        // Acceleration, relative to the link's joint, of the point at unit distance along it:
        // tangential `omega_dot * perp(u)` plus centripetal `-omega^2 u`.
        let k = perp(u) * omega_dot - u * (omega * omega);
        a_com[i] = a_joint + k * links[i].com;
        a_joint += k * links[i].length;
        alpha[i] = omega_dot;
    }

    // Inward pass: `force` is the force link i exerts on link i+1 at joint i+1, `moment` the
    // moment it exerts there; on exit from iteration i they refer to joint i.
    let mut tau = SVector::zeros();
    let mut force = Vector2::zeros();
    let mut moment = 0.0;
    for i in (0..N).rev() {
        let link = &links[i];
        let u = dirs[i];
        let f_com = a_com[i] * link.mass;
        // Euler's equation about joint i (a point with its own acceleration, hence the COM term).
        moment +=
            link.inertia * alpha[i] + link.com * cross(u, f_com) + link.length * cross(u, force);
        force += f_com;
        tau[i] = moment;
    }
    tau
}

/// Composite rigid body algorithm on precomputed link directions.
#[inline(always)]
fn crba_dirs<const N: usize>(links: &[Link; N], dirs: &[Vector2<f64>; N]) -> SMatrix<f64, N, N> {
    let mut m = SMatrix::<f64, N, N>::zeros();
    // Composite body of links j..N about joint j: mass, first moment (world frame, relative to
    // joint j) and rotational inertia.
    let mut mass = 0.0;
    let mut first = Vector2::zeros();
    let mut rot = 0.0;
    for j in (0..N).rev() {
        let link = &links[j];
        let u = dirs[j];
        // Shift the composite of links j+1..N from joint j+1 to joint j (offset d = l_j u_j),
        // then add link j itself.
        let d = u * link.length;
        rot += link.inertia
            + link.mass * link.com * link.com
            + 2.0 * d.dot(&first)
            + mass * link.length * link.length;
        first += u * (link.mass * link.com) + d * mass;
        mass += link.mass;

        // Unit rate at joint j gives the composite angular momentum `rot` about joint j and
        // linear momentum `perp(first)`; its moment about joint i < j adds
        // `(p_j - p_i) x perp(first) = (p_j - p_i) . first`, accumulated link by link.
        let mut mij = rot;
        m[(j, j)] = mij;
        for i in (0..j).rev() {
            mij += links[i].length * dirs[i].dot(&first);
            m[(i, j)] = mij;
            m[(j, i)] = mij;
        }
    }
    m
}

/// Joint torques `tau = M(q) qdd + c(q, qd) + g(q)` by the recursive Newton-Euler algorithm.
///
/// O(N): an outward pass computes each link's angular velocity and acceleration and the linear
/// accelerations of its joint and centre of mass (gravity enters as an upward base acceleration);
/// an inward pass sums forces and moments about each joint.
#[inline]
#[must_use]
pub fn inverse_dynamics<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(links, gravity, &link_directions(q), qd, qdd)
}

/// [`inverse_dynamics`] with the absolute link angles' sines and cosines from
/// [`trig::sin_cos`](crate::trig::sin_cos), all in one call, instead of one `f64::sin_cos` per
/// link: the same recursion with the generated code's trigonometry, so that the benchmarks can
/// tell what the generated code gains from its trigonometry and what from its arithmetic.
#[inline]
#[must_use]
pub fn inverse_dynamics_batched_trig<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    qdd: &SVector<f64, N>,
) -> SVector<f64, N> {
    let dirs = crate::trig::sin_cos(absolute_angles(q)).map(|(s, c)| Vector2::new(c, s));
    rnea_dirs(links, gravity, &dirs, qd, qdd)
}

/// The joint-space mass matrix `M(q)` by the composite rigid body algorithm.
///
/// O(N^2): one inward pass builds the composite mass, first moment and rotational inertia about
/// each joint; the off-diagonal entries follow by shifting each composite's momentum inwards.
#[inline]
#[must_use]
pub fn mass_matrix<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> SMatrix<f64, N, N> {
    crba_dirs(links, &link_directions(q))
}

/// The bias forces `c(q, qd) + g(q)`: [`inverse_dynamics`] with `qdd = 0`.
#[inline]
#[must_use]
pub fn bias_forces<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(links, gravity, &link_directions(q), qd, &SVector::zeros())
}

/// The gravity torques `g(q) = dV/dq`: the joint torques that hold the arm still.
///
/// O(N): joint i must support the weight of links i..N, whose moment about joint i is
/// `gravity` times the horizontal first moment of that composite body.
#[inline]
#[must_use]
pub fn gravity_torques<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
) -> SVector<f64, N> {
    let dirs = link_directions(q);
    let mut tau = SVector::zeros();
    let mut mass = 0.0;
    let mut first_x = 0.0;
    for i in (0..N).rev() {
        let link = &links[i];
        first_x += (link.mass * link.com + mass * link.length) * dirs[i].x;
        mass += link.mass;
        tau[i] = gravity * first_x;
    }
    tau
}

/// The velocity-product (Coriolis and centrifugal) torques `c(q, qd)`: [`inverse_dynamics`]
/// with zero gravity and `qdd = 0`.
#[inline]
#[must_use]
pub fn coriolis<const N: usize>(
    links: &[Link; N],
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> SVector<f64, N> {
    rnea_dirs(links, 0.0, &link_directions(q), qd, &SVector::zeros())
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

/// Joint accelerations `qdd` for applied joint torques `tau` by the articulated body algorithm.
///
/// O(N), and never forms the mass matrix. This is Featherstone's ABA specialised to the plane:
/// spatial vectors are `[angular; x; y]` with 3x3 spatial inertias, all expressed in the world
/// frame about the origin, so that the joint axes are `S_i = [1, y_i, -x_i]` (with `(x_i, y_i)`
/// the joint position) and no coordinate transforms are needed between links. Three passes:
/// velocities and velocity-product terms outwards, articulated inertias and bias forces
/// inwards, accelerations outwards (gravity as an upward base acceleration).
///
/// The result is meaningless (non-finite) if the arm has a degenerate articulated inertia, e.g.
/// a massless, inertialess last link.
#[must_use]
pub fn forward_dynamics<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
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
        let ii = spatial_inertia(link.mass, link.inertia, joint + dirs[i] * link.com);
        bias[i] = cross_force(&v, &(ii * v));
        inertia[i] = ii;
        axis[i] = s;
        joint += dirs[i] * link.length;
    }

    // Pass 2 (inwards): articulated-body inertias and bias forces.
    let mut u_vec = [Vector3::zeros(); N];
    let mut d_inv = [0.0; N];
    let mut u_sc = [0.0; N];
    for i in (0..N).rev() {
        let s = axis[i];
        let u = inertia[i] * s;
        let di = 1.0 / s.dot(&u);
        let ui = tau[i] - s.dot(&bias[i]);
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
    let mut a = Vector3::new(0.0, 0.0, gravity);
    for i in 0..N {
        a += c[i];
        let qddi = (u_sc[i] - u_vec[i].dot(&a)) * d_inv[i];
        a += axis[i] * qddi;
        qdd[i] = qddi;
    }
    qdd
}

/// Joint accelerations `qdd = M^-1 (tau - c - g)` by CRBA, RNEA and a Cholesky solve.
///
/// O(N^3); provided to cross-check and benchmark against [`forward_dynamics`].
///
/// # Panics
///
/// If the mass matrix is not positive definite (only possible with degenerate links, e.g. a
/// massless, inertialess last link).
#[must_use]
pub fn forward_dynamics_crba<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
    tau: &SVector<f64, N>,
) -> SVector<f64, N> {
    let dirs = link_directions(q);
    let m = crba_dirs(links, &dirs);
    let rhs = tau - rnea_dirs(links, gravity, &dirs, qd, &SVector::zeros());
    m.cholesky()
        .expect("the mass matrix of a non-degenerate arm is positive definite")
        .solve(&rhs)
}

/// The kinetic energy `sum(m_i |v_com_i|^2 / 2 + inertia_i omega_i^2 / 2)`, from the
/// centre-of-mass velocities.
#[inline]
#[must_use]
pub fn kinetic_energy<const N: usize>(
    links: &[Link; N],
    q: &SVector<f64, N>,
    qd: &SVector<f64, N>,
) -> f64 {
    let dirs = link_directions(q);
    let mut v_joint = Vector2::zeros();
    let mut omega = 0.0;
    let mut energy = 0.0;
    for i in 0..N {
        let link = &links[i];
        omega += qd[i];
        let k = perp(dirs[i]) * omega;
        let v_com = v_joint + k * link.com;
        energy += link.mass * v_com.norm_squared() + link.inertia * omega * omega;
        v_joint += k * link.length;
    }
    0.5 * energy
}

/// The gravitational potential energy `gravity * sum(m_i y_com_i)`, zero at the base height.
#[inline]
#[must_use]
pub fn potential_energy<const N: usize>(
    links: &[Link; N],
    gravity: f64,
    q: &SVector<f64, N>,
) -> f64 {
    let dirs = link_directions(q);
    let mut y_joint = 0.0;
    let mut moment = 0.0;
    for (link, dir) in links.iter().zip(dirs.iter()) {
        moment += link.mass * (y_joint + link.com * dir.y);
        y_joint += link.length * dir.y;
    }
    gravity * moment
}

/// The position of the tip (the far end of the last link).
#[inline]
#[must_use]
pub fn tip_position<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> Point2<f64> {
    let dirs = link_directions(q);
    let mut tip = Point2::origin();
    for (link, dir) in links.iter().zip(dirs.iter()) {
        tip += dir * link.length;
    }
    tip
}

/// The absolute angle of the last link from +x, `q[0] + ... + q[N-1]` (not wrapped).
#[inline]
#[must_use]
pub fn tip_angle<const N: usize>(q: &SVector<f64, N>) -> f64 {
    q.sum()
}

/// The positions of joints 1..=N; joint 1 is at the origin.
#[inline]
#[must_use]
pub fn joint_positions<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> [Point2<f64>; N] {
    let dirs = link_directions(q);
    let mut joints = [Point2::origin(); N];
    let mut p = Point2::origin();
    for ((joint, link), dir) in joints.iter_mut().zip(links.iter()).zip(dirs.iter()) {
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
pub fn jacobian<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
    let dirs = link_directions(q);
    let mut jac = SMatrix::<f64, 3, N>::zeros();
    // Walk inwards accumulating the vector from joint j to the tip.
    let mut r = Vector2::zeros();
    for j in (0..N).rev() {
        r += dirs[j] * links[j].length;
        jac[(0, j)] = -r.y;
        jac[(1, j)] = r.x;
        jac[(2, j)] = 1.0;
    }
    jac
}

#[cfg(test)]
mod tests {
    use super::*;
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

        fn links<const N: usize>(&mut self) -> [Link; N] {
            core::array::from_fn(|_| {
                let length = self.uniform(0.2, 2.0);
                let mass = self.uniform(0.1, 5.0);
                Link {
                    length,
                    mass,
                    inertia: mass * length * length * self.uniform(0.01, 0.2),
                    // Anywhere along the link, and sometimes a little beyond either end.
                    com: length * self.uniform(-0.2, 1.2),
                }
            })
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

    #[test]
    fn pendulum_by_hand() {
        let link = Link {
            length: 1.3,
            mass: 2.1,
            inertia: 0.37,
            com: 0.55,
        };
        let g = 9.81;
        let mut rng = Rng(1);
        for _ in 0..50 {
            let q = rng.uniform(-4.0, 4.0);
            let qd = rng.uniform(-5.0, 5.0);
            let qdd = rng.uniform(-5.0, 5.0);
            let expected = (link.inertia + link.mass * link.com * link.com) * qdd
                + link.mass * g * link.com * q.cos();
            let got = inverse_dynamics(
                &[link],
                g,
                &SVector::from([q]),
                &SVector::from([qd]),
                &SVector::from([qdd]),
            );
            assert_close_f(got[0], expected, 1e-13, "pendulum");
        }
    }

    /// The textbook closed form of the general two-link arm.
    fn two_link_closed_form(
        links: &[Link; 2],
        g: f64,
        q: &V2<f64>,
        qd: &V2<f64>,
    ) -> (Matrix2<f64>, V2<f64>, V2<f64>) {
        let [a, b] = *links;
        let (i1, i2, m1, m2, l1, c1, c2) =
            (a.inertia, b.inertia, a.mass, b.mass, a.length, a.com, b.com);
        let cos2 = q[1].cos();
        let m11 = i1 + i2 + m1 * c1 * c1 + m2 * (l1 * l1 + c2 * c2 + 2.0 * l1 * c2 * cos2);
        let m12 = i2 + m2 * (c2 * c2 + l1 * c2 * cos2);
        let m22 = i2 + m2 * c2 * c2;
        let h = m2 * l1 * c2 * q[1].sin();
        let c = V2::new(
            -h * qd[1] * qd[1] - 2.0 * h * qd[0] * qd[1],
            h * qd[0] * qd[0],
        );
        let cos12 = (q[0] + q[1]).cos();
        let grav = V2::new(
            g * (m1 * c1 + m2 * l1) * q[0].cos() + g * m2 * c2 * cos12,
            g * m2 * c2 * cos12,
        );
        (Matrix2::new(m11, m12, m12, m22), c, grav)
    }

    #[test]
    fn two_link_matches_closed_form() {
        let mut rng = Rng(2);
        for _ in 0..200 {
            let links: [Link; 2] = rng.links();
            let g = rng.uniform(0.0, 15.0);
            let q = rng.vector::<2>(4.0);
            let qd = rng.vector::<2>(5.0);
            let qdd = rng.vector::<2>(5.0);
            let (m, c, grav) = two_link_closed_form(&links, g, &q, &qd);
            assert_close(&mass_matrix(&links, &q), &m, 1e-13, "M");
            assert_close(&coriolis(&links, &q, &qd), &c, 1e-13, "c");
            assert_close(&gravity_torques(&links, g, &q), &grav, 1e-13, "g");
            assert_close(
                &bias_forces(&links, g, &q, &qd),
                &(c + grav),
                1e-13,
                "c + g",
            );
            assert_close(
                &inverse_dynamics(&links, g, &q, &qd, &qdd),
                &(m * qdd + c + grav),
                1e-13,
                "tau",
            );
        }
    }

    #[test]
    fn paper_equal_rods_mass_matrix() {
        let links = [Link::rod(1.0, 1.0); 2];
        for q2 in [0.0_f64, 0.4, 1.0, -2.5, 3.0] {
            let q = SVector::from([0.7, q2]);
            let c = q2.cos();
            let expected = Matrix2::new(
                5.0 / 3.0 + c,
                1.0 / 3.0 + c / 2.0,
                1.0 / 3.0 + c / 2.0,
                1.0 / 3.0,
            );
            assert_close(&mass_matrix(&links, &q), &expected, 1e-15, "paper M");
        }
    }

    /// `value` times the j-th standard basis vector.
    fn basis<const N: usize>(j: usize, value: f64) -> SVector<f64, N> {
        SVector::from_fn(|i, _| if i == j { value } else { 0.0 })
    }

    /// All the cross-checks between algorithms for one random arm and state.
    fn cross_check<const N: usize>(rng: &mut Rng) {
        let links: [Link; N] = rng.links();
        let g = rng.uniform(0.0, 15.0);
        let q = rng.vector::<N>(std::f64::consts::PI);
        let qd = rng.vector::<N>(3.0);
        let tau = rng.vector::<N>(20.0);
        let zero = SVector::<f64, N>::zeros();
        let tol = 1e-10;

        // CRBA against columns of RNEA(qd = 0, g = 0, qdd = e_j).
        let m = mass_matrix(&links, &q);
        let m_rnea = SMatrix::<f64, N, N>::from_fn(|i, j| {
            inverse_dynamics(&links, 0.0, &q, &zero, &basis(j, 1.0))[i]
        });
        assert_close(&m, &m_rnea, tol, "CRBA vs RNEA columns");
        assert_close(&m, &m.transpose(), 0.0, "M symmetric");

        // Bias decomposition.
        let bias = bias_forces(&links, g, &q, &qd);
        let grav = gravity_torques(&links, g, &q);
        let cor = coriolis(&links, &q, &qd);
        assert_close(&bias, &(cor + grav), tol, "bias = c + g");
        assert_close(
            &grav,
            &inverse_dynamics(&links, g, &q, &zero, &zero),
            tol,
            "g vs RNEA",
        );

        // ABA against CRBA + Cholesky, and round trip through inverse dynamics.
        let qdd_aba = forward_dynamics(&links, g, &q, &qd, &tau);
        let qdd_crba = forward_dynamics_crba(&links, g, &q, &qd, &tau);
        assert_close(&qdd_aba, &qdd_crba, tol, "ABA vs CRBA");
        assert_close(
            &inverse_dynamics(&links, g, &q, &qd, &qdd_aba),
            &tau,
            tol,
            "RNEA(ABA(tau))",
        );
        assert_close(&(m * qdd_aba + bias), &tau, tol, "M qdd + bias = tau");

        // Kinetic energy against the mass matrix.
        assert_close_f(
            kinetic_energy(&links, &q, &qd),
            0.5 * qd.dot(&(m * qd)),
            tol,
            "T = qd' M qd / 2",
        );

        // Gravity torques and Jacobian against central finite differences.
        let h = 1e-6;
        let fd_tol = 1e-7;
        let mut jac_fd = SMatrix::<f64, 3, N>::zeros();
        for j in 0..N {
            let dq = basis::<N>(j, h);
            let (qp, qm) = (q + dq, q - dq);
            let dv =
                (potential_energy(&links, g, &qp) - potential_energy(&links, g, &qm)) / (2.0 * h);
            assert_close_f(grav[j], dv, fd_tol, "g = dV/dq");
            let dp = (tip_position(&links, &qp) - tip_position(&links, &qm)) / (2.0 * h);
            let da = (tip_angle(&qp) - tip_angle(&qm)) / (2.0 * h);
            jac_fd.set_column(j, &Vector3::new(dp.x, dp.y, da));
        }
        assert_close(&jacobian(&links, &q), &jac_fd, fd_tol, "Jacobian");

        // Joint 1 at the origin; the last link runs from the last joint to the tip along the
        // tip angle.
        let joints = joint_positions(&links, &q);
        assert_eq!(joints[0], Point2::origin());
        let last_link = tip_position(&links, &q) - joints[N - 1];
        let (s, c) = tip_angle(&q).sin_cos();
        assert_close(
            &last_link,
            &(V2::new(c, s) * links[N - 1].length),
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

    #[test]
    fn kinematics_by_hand() {
        let links = [
            Link::rod(1.0, 1.0),
            Link::rod(2.0, 1.0),
            Link::rod(0.5, 1.0),
        ];
        let q = SVector::from([
            std::f64::consts::FRAC_PI_2,
            -std::f64::consts::FRAC_PI_2,
            0.0,
        ]);
        let joints = joint_positions(&links, &q);
        assert_close(&joints[1].coords, &V2::new(0.0, 1.0), 1e-15, "joint 2");
        assert_close(&joints[2].coords, &V2::new(2.0, 1.0), 1e-15, "joint 3");
        assert_close(
            &tip_position(&links, &q).coords,
            &V2::new(2.5, 1.0),
            1e-15,
            "tip",
        );
        assert_close_f(tip_angle(&q), 0.0, 0.0, "tip angle");
        // Joint 3 rotates only the last link: tip velocity perp((0.5, 0)) = (0, 0.5).
        let jac = jacobian(&links, &q);
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
        let link = Link::rod(2.0, 3.0);
        let w = 1.5;
        let joint_inertia = 3.0 * 4.0 / 3.0;
        assert_close_f(
            kinetic_energy(&[link], &SVector::from([0.3]), &SVector::from([w])),
            0.5 * joint_inertia * w * w,
            1e-15,
            "rod T",
        );
        let v = potential_energy(&[link], 9.81, &SVector::from([std::f64::consts::FRAC_PI_2]));
        assert_close_f(v, 9.81 * 3.0 * 1.0, 1e-15, "rod V");
    }
}
