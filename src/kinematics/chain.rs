//! Forward kinematics and the Jacobian of any mix of revolute and prismatic joints, from the
//! links alone, and random tip positions within the joint ranges for drawing a work-space.

use core::f64::consts::PI;
#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Complex, Isometry2, Point2, SMatrix, SVector, UnitComplex, Vector2};

use super::statics::angle_sum;
use crate::{Joint, Link};

/// One step of the chain: the joint's origin `o_i` and the direction `(sin, cos)` it slides
/// along (the previous link's).
struct Step {
    origin: Vector2<f64>,
    along: (f64, f64),
}

/// Walks the chain by the rules of [`Joint`]: revolute joint `i` turns by `q_i` and sits at
/// the previous link's end, prismatic joint `i` keeps the direction and sits `q_i` further
/// along the previous link (along +x before the first). Calls `visit` with each joint's
/// index and [`Step`]; returns the tip and the `(sin, cos)` of the last link's absolute angle,
/// composed from each joint's sine and cosine (accurate for any finite angle).
fn walk(
    links: &[Link],
    mut q: impl FnMut(usize) -> f64,
    mut visit: impl FnMut(usize, &Step),
) -> (Vector2<f64>, (f64, f64)) {
    let mut at = Vector2::zeros();
    let mut direction = (0.0, 1.0);
    let mut previous = 0.0;
    for (i, link) in links.iter().enumerate() {
        let qi = q(i);
        let advance = match link.joint {
            Joint::Revolute => previous,
            Joint::Prismatic => previous + qi,
        };
        let (s, c) = direction;
        at += Vector2::new(c, s) * advance;
        visit(
            i,
            &Step {
                origin: at,
                along: direction,
            },
        );
        if link.joint == Joint::Revolute {
            direction = angle_sum(direction, qi.sin_cos());
        }
        previous = link.length;
    }
    let (s, c) = direction;
    (at + Vector2::new(c, s) * previous, direction)
}

/// The tip pose of an arm of these links at `q`: the position of the end of the last link
/// and its absolute angle, for any mix of joint kinds (what a derived arm's
/// [`tip_pose`](crate::PlanarArm::tip_pose) gives, computed from the links at run time).
///
/// Joint `i` acts by the rules of [`Joint`]: revolute, `phi_i = phi_{i-1} + q_i` and
/// `o_i = o_{i-1} + l_{i-1} u_{i-1}`; prismatic, `phi_i = phi_{i-1}` and
/// `o_i = o_{i-1} + (l_{i-1} + q_i) u_{i-1}`, with `u = (cos phi, sin phi)`, `phi = 0` and no
/// link before the first. The tip is `o_{N-1} + l_{N-1} u_{N-1}`. Ranges are not applied.
///
/// # Example
/// ```
/// use planar_arm::kinematics::tip_pose_of;
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::{Joint, Link};
///
/// // The polar arm: tip = (0.2 + q2 + 0.5) (cos q1, sin q1).
/// let polar = [Link::rod(0.2, 1.0), Link::rod(0.5, 1.0).with_joint(Joint::Prismatic)];
/// let pose = tip_pose_of(&polar, &Vector2::new(0.5, 0.3));
/// let expected = Vector2::new(0.5_f64.cos(), 0.5_f64.sin());
/// assert!((pose.translation.vector - expected).norm() < 1e-15);
/// assert!((pose.rotation.angle() - 0.5).abs() < 1e-15);
/// ```
#[must_use]
pub fn tip_pose_of<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> Isometry2<f64> {
    let (tip, (s, c)) = walk(links, |i| q[i], |_, _| {});
    Isometry2::from_parts(tip.into(), UnitComplex::from_complex(Complex::new(c, s)))
}

/// The 3 x N Jacobian of [`tip_pose_of`]: rows d/dt of tip x, tip y and the last link's angle.
///
/// Column `i` of a revolute joint at `o_i` is `(-(y_tip - y_i), x_tip - x_i, 1)`; of a
/// prismatic joint, `(cos phi_{i-1}, sin phi_{i-1}, 0)`, the direction it slides along (a
/// velocity per unit slide, and a generalised force `F . u` in newtons).
///
/// # Example
/// ```
/// use planar_arm::kinematics::jacobian_of;
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::{Joint, Link};
///
/// let slider = [Link::rod(0.3, 1.0).with_joint(Joint::Prismatic), Link::rod(0.5, 1.0)];
/// let j = jacobian_of(&slider, &Vector2::new(0.4, std::f64::consts::FRAC_PI_2));
/// // The slide moves the tip along +x; the hinge turns the 0.5 m link pointing up.
/// assert_eq!(j.column(0).as_slice(), &[1.0, 0.0, 0.0]);
/// assert!((j[(0, 1)] + 0.5).abs() < 1e-15 && j[(1, 1)].abs() < 1e-15 && j[(2, 1)] == 1.0);
/// ```
#[must_use]
pub fn jacobian_of<const N: usize>(links: &[Link; N], q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
    let mut steps = [(Vector2::zeros(), (0.0, 1.0)); N];
    let (tip, _) = walk(
        links,
        |i| q[i],
        |i, step| steps[i] = (step.origin, step.along),
    );
    SMatrix::from_fn(|row, i| {
        let (origin, (s, c)) = steps[i];
        match (links[i].joint, row) {
            (Joint::Revolute, 0) => -(tip.y - origin.y),
            (Joint::Revolute, 1) => tip.x - origin.x,
            (Joint::Revolute, _) => 1.0,
            (Joint::Prismatic, 0) => c,
            (Joint::Prismatic, 1) => s,
            (Joint::Prismatic, _) => 0.0,
        }
    })
}

/// The tip positions of random configurations of an arm's links within their ranges, for
/// drawing its work-space: an endless iterator ([`sample_tips`]).
#[derive(Debug, Clone)]
pub struct TipSamples<'a> {
    links: &'a [Link],
    free_slide: f64,
    state: u64,
}

/// Random tip positions of an arm of these links (any number, any mix of joints), each joint
/// drawn uniformly within its range: a revolute joint without a range over (-pi, pi], a
/// prismatic one without a range over `-free_slide ..= free_slide` metres. Deterministic for a
/// `seed` (splitmix64); endless, so take what you need. Uses no heap.
///
/// The density of the tips is not uniform over the work-space (it follows the joints), so use
/// it to show where the tip goes, and [`Workspace`](super::Workspace) for the region itself.
///
/// # Example
/// ```
/// use planar_arm::kinematics::{sample_tips, Workspace};
/// use planar_arm::{Joint, Link};
///
/// let polar = [
///     Link::rod(0.2, 1.0).with_range(-1.0, 1.0),
///     Link::rod(0.5, 1.0).with_joint(Joint::Prismatic).with_range(0.1, 0.6),
/// ];
/// let w = Workspace::of_links(&polar);
/// assert!(sample_tips(&polar, 1.0, 7).take(1000).all(|p| w.contains(&p)));
/// ```
#[must_use]
pub fn sample_tips(links: &[Link], free_slide: f64, seed: u64) -> TipSamples<'_> {
    TipSamples {
        links,
        free_slide,
        state: seed,
    }
}

impl TipSamples<'_> {
    /// A number in [0, 1) (splitmix64).
    fn unit(&mut self) -> f64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        #[allow(clippy::cast_precision_loss)] // 53 bits, exactly representable
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        u
    }
}

impl Iterator for TipSamples<'_> {
    type Item = Point2<f64>;

    fn next(&mut self) -> Option<Point2<f64>> {
        let links = self.links;
        let free = self.free_slide;
        let (tip, _) = walk(
            links,
            |i| {
                let u = self.unit();
                let (lo, hi) = match (links[i].joint, links[i].range) {
                    (_, Some(range)) => range,
                    (Joint::Revolute, None) => (-PI, PI),
                    (Joint::Prismatic, None) => (-free, free),
                };
                lo + (hi - lo) * u
            },
            |_, _| {},
        );
        Some(tip.into())
    }
}

/// Every joint origin `o_i` (joint 1 first) and the tip of an arm of these links at `q`, by the
/// rules of [`tip_pose_of`]: for a prismatic joint `i` the origin is where link `i` starts.
pub(super) fn joint_origins<const N: usize>(
    links: &[Link; N],
    q: &SVector<f64, N>,
) -> ([Point2<f64>; N], Point2<f64>) {
    let mut origins = [Point2::origin(); N];
    let (tip, _) = walk(links, |i| q[i], |i, step| origins[i] = step.origin.into());
    (origins, tip.into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{fk_joints, jacobian, Rng};
    use nalgebra::Vector3;

    const R: Joint = Joint::Revolute;
    const P: Joint = Joint::Prismatic;

    fn links<const N: usize>(kinds: [Joint; N], lengths: [f64; N]) -> [Link; N] {
        core::array::from_fn(|i| Link::rod(lengths[i], 1.0).with_joint(kinds[i]))
    }

    fn check<const N: usize>(kinds: [Joint; N], lengths: [f64; N], rng: &mut Rng) {
        let arm = links(kinds, lengths);
        for _ in 0..200 {
            let q = SVector::<f64, N>::from_fn(|_, _| rng.range(-2.0, 2.0));
            let (x, y, phi) = fk_joints(&kinds, &lengths, q.as_slice());
            let pose = tip_pose_of(&arm, &q);
            assert!((pose.translation.vector - Vector2::new(x, y)).norm() < 1e-14);
            assert!(super::super::wrap_angle(pose.rotation.angle() - phi).abs() < 1e-14);
            // Central differences of the independent forward kinematics.
            let j = jacobian_of(&arm, &q);
            for i in 0..N {
                let h = 1e-6;
                let (mut qp, mut qm) = (q, q);
                qp[i] += h;
                qm[i] -= h;
                let (xp, yp, pp) = fk_joints(&kinds, &lengths, qp.as_slice());
                let (xm, ym, pm) = fk_joints(&kinds, &lengths, qm.as_slice());
                let d = Vector3::new(xp - xm, yp - ym, pp - pm) / (2.0 * h);
                assert!((d - j.column(i)).norm() < 1e-8, "{kinds:?} column {i}");
            }
            let (origins, tip) = joint_origins(&arm, &q);
            assert!((tip.coords - Vector2::new(x, y)).norm() < 1e-14);
            // Each origin is the tip of the arm cut after the previous link with the joint
            // applied: the prefix's tip with a zero-length link i.
            for i in 0..N {
                let mut cut = lengths;
                cut[i] = 0.0;
                let (ox, oy, _) = fk_joints(&kinds[..=i], &cut[..=i], &q.as_slice()[..=i]);
                assert!((origins[i].coords - Vector2::new(ox, oy)).norm() < 1e-14);
            }
        }
    }

    #[test]
    fn forward_kinematics_and_jacobian_of_any_mix() {
        let mut rng = Rng(27);
        check([R, P], [0.2, 0.5], &mut rng);
        check([P, R], [0.3, 0.5], &mut rng);
        check([P, R, R], [0.2, 0.5, 0.3], &mut rng);
        check([R, P, R, P], [0.4, 1.0, 0.3, 0.2], &mut rng);
        check([P, P, R], [0.1, 0.2, 0.3], &mut rng);
        check([R, R, R, R], [1.0, 0.7, 0.3, 0.9], &mut rng);
        // All revolute: the revolute Jacobian the other files test against.
        let arm = links([R; 3], [1.0, 0.7, 0.3]);
        let q = Vector3::new(0.3, -1.2, 2.0);
        assert!((jacobian_of(&arm, &q) - jacobian(&[1.0, 0.7, 0.3], &q)).norm() < 1e-15);
    }

    #[test]
    fn samples_stay_within_the_ranges() {
        let arm = [
            Link::rod(0.2, 1.0).with_range(0.0, 0.5),
            Link::rod(0.5, 1.0).with_joint(P).with_range(0.1, 0.6),
        ];
        let mut count = 0;
        for p in sample_tips(&arm, 1.0, 3).take(5000) {
            let (r, theta) = (p.coords.norm(), p.y.atan2(p.x));
            assert!((0.8 - 1e-12..=1.3 + 1e-12).contains(&r), "{r}");
            assert!((-1e-12..=0.5 + 1e-12).contains(&theta), "{theta}");
            count += 1;
        }
        assert_eq!(count, 5000);
        // A slide without a range: within the free travel.
        let free = [Link::rod(0.3, 1.0).with_joint(P), Link::rod(0.5, 1.0)];
        assert!(sample_tips(&free, 2.0, 4)
            .take(2000)
            .all(|p| p.x.abs() <= 2.8 + 1e-12 && p.y.abs() <= 0.5 + 1e-12));
    }
}
