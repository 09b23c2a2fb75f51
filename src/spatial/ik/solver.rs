//! [`SpatialIk`]: the closed-form inverse kinematics of six-joint arms whose geometry decouples
//! position from orientation.
//!
//! The arm is described by its joint axes at `q = 0` (a point and a unit direction each) and the
//! tool pose there, `home`: by the product of exponentials, the tool at `q` is
//! `exp(xi_1 q_1) ... exp(xi_6 q_6) home`, whatever convention wrote the arm. Three classes
//! cover industry:
//!
//! - [`IkClass::SphericalWrist`]: joints 1-3 revolute with axes 2 and 3 parallel (PUMA, KUKA,
//!   ABB, Fanuc, Staubli), axes 4, 5, 6 meeting in the wrist centre `c`;
//! - [`IkClass::SlidingWrist`]: joints 1 and 2 revolute with intersecting axes, joint 3
//!   prismatic (the Stanford arm), axes 4, 5, 6 meeting in `c`;
//! - [`IkClass::ParallelTriple`]: all revolute, axes 2, 3, 4 parallel, axes 5 and 6 meeting in
//!   `c` (the UR family).
//!
//! `c` is fixed in the tool's frame, so the target gives its position. Joint 1 is found from
//! the plane that joints 2-4 move in (parallel axes) or from the distance to the shoulder
//! (intersecting axes); the next joints by planar geometry or two rotations about
//! intersecting axes; the wrist by two rotations about intersecting axes and one about the
//! last. Every branch is returned: up to 2 x 2 x 2 = 8 solutions.

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{Isometry3, Point3, SVector, Vector3};

use super::subproblems::{angle_about, cos_sin, rotate, two_axes, Trig};
use super::IkSolutions;
use crate::kinematics::REACH_TOLERANCE;
use crate::{ArmError, Joint};

/// Which decoupling a six-joint arm allows (see the module's docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IkClass {
    /// Revolute 1-3 with axes 2 and 3 parallel, axes 4-6 meeting in a point.
    SphericalWrist,
    /// Revolute 1 and 2 with intersecting axes, prismatic 3, axes 4-6 meeting in a point.
    SlidingWrist,
    /// Revolute 1-6 with axes 2, 3, 4 parallel and axes 5 and 6 meeting in a point.
    ParallelTriple,
}

/// A six-joint arm as its closed-form inverse kinematics sees it: joint axes at `q = 0`, the
/// tool pose there and the point `c` the decoupling turns on (see the module's docs).
///
/// `#[derive(SpatialArm)]` builds it with constants for arms it classifies from their exact
/// geometry; [`SpatialIk::of_model`] classifies a numeric model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialIk {
    /// The class.
    pub class: IkClass,
    /// A point on each joint's axis at `q = 0`, base frame.
    pub points: [Vector3<f64>; 6],
    /// Each joint's unit axis at `q = 0`, base frame.
    pub axes: [Vector3<f64>; 6],
    /// The tool pose at `q = 0`.
    pub home: Isometry3<f64>,
    /// The wrist centre (axes 4-6) or the meeting point of axes 5 and 6, at `q = 0`.
    pub centre: Vector3<f64>,
    /// The arm's scale (the largest distance of a point above from the base): the reach
    /// tolerances are [`REACH_TOLERANCE`] times it.
    pub scale: f64,
}

/// A joint-1 (or first-stage) candidate and what it leaves to solve.
type Partial = [f64; 6];

impl SpatialIk {
    /// Every solution for the tool pose `target`, each angle in (-pi, pi] or the representative
    /// in its range, solutions outside `ranges` dropped.
    ///
    /// # Errors
    /// [`ArmError::NonFinite`] for a target holding NaN or infinities;
    /// [`ArmError::OutOfReach`] when the point `c` or (for the parallel class) the tool axis
    /// cannot be placed, by how much; [`ArmError::BeyondJointRange`] when solutions exist but
    /// none lies within the ranges.
    pub fn solve(
        &self,
        target: &Isometry3<f64>,
        ranges: &[Option<(f64, f64)>; 6],
    ) -> Result<IkSolutions<6>, ArmError> {
        let finite = target.translation.vector.iter().all(|x| x.is_finite())
            && target.rotation.coords.iter().all(|x| x.is_finite());
        if !finite {
            return Err(ArmError::NonFinite { argument: "target" });
        }
        let mut all = IkSolutions::new();
        let centre = target * self.home.inverse() * Point3::from(self.centre);
        let reach = match self.class {
            IkClass::SphericalWrist => self.spherical(target, &centre.coords, &mut all),
            IkClass::SlidingWrist => self.sliding(target, &centre.coords, &mut all),
            IkClass::ParallelTriple => self.parallel(target, &centre.coords, &mut all),
        };
        if let Err(miss) = reach {
            let t = target.translation.vector;
            return Err(ArmError::OutOfReach {
                target: [t.x, t.y, t.z],
                what: miss.what,
                distance: miss.distance,
                unit: miss.unit,
            });
        }
        let kinds = self.kinds();
        super::ranges::keep_within(&all, &kinds, ranges, self.slack())
    }

    /// The kinds of the six joints the class implies.
    #[must_use]
    pub fn kinds(&self) -> [Joint; 6] {
        let mut kinds = [Joint::Revolute; 6];
        if self.class == IkClass::SlidingWrist {
            kinds[2] = Joint::Prismatic;
        }
        kinds
    }

    fn slack(&self) -> f64 {
        REACH_TOLERANCE * self.scale.max(f64::MIN_POSITIVE)
    }

    /// Joint `i`'s rotation applied to a point (a slide's translation).
    fn move_point(&self, i: usize, q: f64, p: &Vector3<f64>) -> Vector3<f64> {
        match self.kinds()[i] {
            Joint::Revolute => self.points[i] + rotate(&self.axes[i], q, &(p - self.points[i])),
            Joint::Prismatic => p + self.axes[i] * q,
        }
    }

    /// The inverse of the first joints' rotation, `(R_1 ... R_k)^T v`, slides contributing none.
    fn unturn(&self, q: &[f64], v: &Vector3<f64>) -> Vector3<f64> {
        let mut out = *v;
        for (i, qi) in q.iter().enumerate() {
            if self.kinds()[i] == Joint::Revolute {
                out = rotate(&self.axes[i], -qi, &out);
            }
        }
        out
    }

    /// The joint-1 angles that bring `point` (where the tracked point must go) into the plane
    /// through `on_plane` across the parallel axes' direction `u`.
    fn first_angle(
        &self,
        u: &Vector3<f64>,
        point: &Vector3<f64>,
        on_plane: &Vector3<f64>,
        singular: &mut bool,
    ) -> Result<[f64; 2], Miss> {
        let (r1, w1) = (self.points[0], self.axes[0]);
        let v = point - r1;
        let v_along = w1 * w1.dot(&v);
        let v_across = v - v_along;
        // u . (r1 + R(w1, -t) v) = u . on_plane
        let a = u.dot(&v_across);
        let b = -u.dot(&w1.cross(&v));
        let c = u.dot(&(on_plane - r1)) - u.dot(&v_along);
        match cos_sin(a, b, c, self.slack()) {
            Trig::Two(t) => Ok(t),
            Trig::Any => {
                *singular = true;
                Ok([0.0; 2])
            }
            Trig::None(by) => Err(Miss::metres("the wrist centre's plane", by)),
        }
    }

    /// The two elbow solutions `(t2, t3)` of joints 2 and 3 (parallel axes) taking `from` (at
    /// `q = 0`) to `to`, both in one plane across the axes.
    fn planar(
        &self,
        from: &Vector3<f64>,
        to: &Vector3<f64>,
        singular: &mut bool,
    ) -> Result<[[f64; 2]; 2], Miss> {
        let (w2, w3) = (self.axes[1], self.axes[2]);
        let on_plane = |r: &Vector3<f64>| r + w2 * w2.dot(&(from - r));
        let (c2, c3) = (on_plane(&self.points[1]), on_plane(&self.points[2]));
        let to = to - w2 * w2.dot(&(to - from));
        let (v, e) = (from - c3, c3 - c2);
        let delta2 = (to - c2).norm_squared();
        let a = e.dot(&v);
        let b = e.dot(&w3.cross(&v));
        let c = 0.5 * (delta2 - e.norm_squared() - v.norm_squared());
        let t3 = match cos_sin(a, b, c, self.slack() * (e.norm() + v.norm())) {
            Trig::Two(t) => t,
            Trig::Any => {
                *singular = true;
                [0.0; 2]
            }
            Trig::None(_) => {
                let delta = delta2.sqrt();
                let (near, far) = ((e.norm() - v.norm()).abs(), e.norm() + v.norm());
                return Err(Miss::metres(
                    "the elbow's annulus",
                    (delta - far).max(near - delta),
                ));
            }
        };
        Ok(t3.map(|t3| {
            let moved = c3 + rotate(&w3, t3, &v);
            let t2 = angle_about(&w2, &(moved - c2), &(to - c2));
            [t2, t3]
        }))
    }

    fn spherical(
        &self,
        target: &Isometry3<f64>,
        centre: &Vector3<f64>,
        out: &mut IkSolutions<6>,
    ) -> Result<(), Miss> {
        let mut singular = false;
        let u = self.axes[1];
        let mut firsts: [Option<Partial>; 4] = [None; 4];
        let mut miss = None;
        for (k, t1) in self
            .first_angle(&u, centre, &self.centre, &mut singular)?
            .into_iter()
            .enumerate()
        {
            let back = self.move_point(0, -t1, centre);
            match self.planar(&self.centre, &back, &mut singular) {
                Ok(pairs) => {
                    for (m, [t2, t3]) in pairs.into_iter().enumerate() {
                        firsts[2 * k + m] = Some([t1, t2, t3, 0.0, 0.0, 0.0]);
                    }
                }
                Err(e) => miss = Some(e),
            }
        }
        self.finish_wrist(target, &firsts, miss, singular, out)
    }

    fn sliding(
        &self,
        target: &Isometry3<f64>,
        centre: &Vector3<f64>,
        out: &mut IkSolutions<6>,
    ) -> Result<(), Miss> {
        let shoulder = closest_point(
            &self.points[0],
            &self.axes[0],
            &self.points[1],
            &self.axes[1],
        );
        let a = self.centre - shoulder;
        let w3 = self.axes[2];
        let reach2 = (centre - shoulder).norm_squared();
        // |a + d w3|^2 = reach^2
        let half_b = a.dot(&w3);
        let disc = half_b * half_b - a.norm_squared() + reach2;
        let slack = self.slack() * self.scale.max(f64::MIN_POSITIVE);
        if disc < -slack {
            let closest = (a.norm_squared() - half_b * half_b).max(0.0).sqrt();
            return Err(Miss::metres("the wrist centre", closest - reach2.sqrt()));
        }
        let root = disc.max(0.0).sqrt();
        let mut firsts: [Option<Partial>; 4] = [None; 4];
        let mut miss = None;
        for (k, d) in [-half_b + root, -half_b - root].into_iter().enumerate() {
            let p = a + w3 * d;
            match two_axes(
                &self.axes[0],
                &self.axes[1],
                &p,
                &(centre - shoulder),
                slack,
            ) {
                Ok(zs) => {
                    for (m, z) in zs.into_iter().enumerate() {
                        let t2 = angle_about(&self.axes[1], &p, &z);
                        let t1 = angle_about(&self.axes[0], &z, &(centre - shoulder));
                        firsts[2 * k + m] = Some([t1, t2, d, 0.0, 0.0, 0.0]);
                    }
                }
                Err(by) => miss = Some(Miss::metres("the wrist centre", by.sqrt())),
            }
        }
        self.finish_wrist(target, &firsts, miss, false, out)
    }

    /// For each position solution, both wrist solutions: `R(w4, t4) R(w5, t5) R(w6, t6)` equal
    /// to what the first three joints leave of the target's rotation.
    fn finish_wrist(
        &self,
        target: &Isometry3<f64>,
        firsts: &[Option<Partial>; 4],
        miss: Option<Miss>,
        mut singular: bool,
        out: &mut IkSolutions<6>,
    ) -> Result<(), Miss> {
        let rest = target.rotation * self.home.rotation.inverse();
        let mut any = false;
        for partial in firsts.iter().flatten() {
            let relative = |v: &Vector3<f64>| self.unturn(&partial[..3], &(rest * v));
            let (w4, w5, w6) = (self.axes[3], self.axes[4], self.axes[5]);
            let Ok(zs) = two_axes(&w4, &w5, &w6, &relative(&w6), 1e-12) else {
                continue;
            };
            for z in zs {
                // On the singularity z lies along w4 and t4 is free: t4 = 0 represents it.
                let along = (z - w4 * w4.dot(&z)).norm() < 1e-9;
                singular |= along;
                let t4 = if along {
                    0.0
                } else {
                    angle_about(&w4, &z, &relative(&w6))
                };
                let t5 = angle_about(&w5, &w6, &z);
                let across = any_across(&w6);
                let seen = rotate(&w5, -t5, &rotate(&w4, -t4, &relative(&across)));
                let t6 = angle_about(&w6, &across, &seen);
                out.push(SVector::from([
                    partial[0], partial[1], partial[2], t4, t5, t6,
                ]));
                any = true;
            }
        }
        if singular {
            out.mark_singular();
        }
        match (any, miss) {
            (false, Some(m)) => Err(m),
            (false, None) => Err(Miss::radians("the wrist's orientation", 0.0)),
            _ => Ok(()),
        }
    }

    fn parallel(
        &self,
        target: &Isometry3<f64>,
        centre: &Vector3<f64>,
        out: &mut IkSolutions<6>,
    ) -> Result<(), Miss> {
        let mut singular = false;
        let u = self.axes[1];
        let signs = [1usize, 2, 3].map(|i| {
            if self.axes[i].dot(&u) > 0.0 {
                1.0
            } else {
                -1.0
            }
        });
        let rest = target.rotation * self.home.rotation.inverse();
        let (w5, w6) = (self.axes[4], self.axes[5]);
        let mut miss = None;
        let mut any = false;
        for t1 in self.first_angle(&u, centre, &self.centre, &mut singular)? {
            // N = R1^T rest = R(u, theta) R5 R6.
            let n = |v: &Vector3<f64>| rotate(&self.axes[0], -t1, &(rest * v));
            let n_t = |v: &Vector3<f64>| rest.inverse() * rotate(&self.axes[0], t1, v);
            // u . N w6 = u . R(w5, t5) w6
            let w6_across = w6 - w5 * w5.dot(&w6);
            let a = u.dot(&w6_across);
            let b = u.dot(&w5.cross(&w6));
            let c = u.dot(&n(&w6)) - u.dot(&w5) * w5.dot(&w6);
            let fives = match cos_sin(a, b, c, 1e-12) {
                Trig::Two(t) => t,
                Trig::Any => {
                    singular = true;
                    [0.0; 2]
                }
                Trig::None(by) => {
                    miss = Some(Miss::radians("the tool axis", by));
                    continue;
                }
            };
            for t5 in fives {
                // R(w6, -t6) (R5^T u) = N^T u
                let from = rotate(&w5, -t5, &u);
                let free = (from - w6 * w6.dot(&from)).norm() < 1e-9;
                singular |= free;
                let t6 = if free {
                    0.0
                } else {
                    -angle_about(&w6, &from, &n_t(&u))
                };
                // R(u, theta) = N R6^T R5^T on a vector across u.
                let across = any_across(&u);
                let seen = n(&rotate(&w6, -t6, &rotate(&w5, -t5, &across)));
                let theta = angle_about(&u, &across, &seen);
                // The point on axis 4, where joints 2 and 3 must put it.
                let back = self.move_point(0, -t1, centre);
                let r4 = self.points[3];
                let wanted = back - rotate(&u, theta, &(self.centre - r4));
                match self.planar(&r4, &wanted, &mut singular) {
                    Ok(pairs) => {
                        for [t2, t3] in pairs {
                            let t4 = signs[2] * (theta - signs[0] * t2 - signs[1] * t3);
                            out.push(SVector::from([t1, t2, t3, t4, t5, t6]));
                            any = true;
                        }
                    }
                    Err(e) => miss = Some(e),
                }
            }
        }
        if singular {
            out.mark_singular();
        }
        match (any, miss) {
            (false, Some(m)) => Err(m),
            _ => Ok(()),
        }
    }
}

/// Why a target is out of reach, before it is an [`ArmError`].
#[derive(Debug, Clone, Copy)]
struct Miss {
    what: &'static str,
    distance: f64,
    unit: &'static str,
}

impl Miss {
    fn metres(what: &'static str, distance: f64) -> Self {
        Self {
            what,
            distance: distance.max(f64::MIN_POSITIVE),
            unit: "m",
        }
    }
    fn radians(what: &'static str, distance: f64) -> Self {
        Self {
            what,
            distance: distance.max(f64::MIN_POSITIVE),
            unit: "rad",
        }
    }
}

/// A unit vector across `w` (unit).
fn any_across(w: &Vector3<f64>) -> Vector3<f64> {
    let e = if w.x.abs() < 0.6 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    w.cross(&e).normalize()
}

/// The point of line `(p1, w1)` nearest line `(p2, w2)`; for intersecting lines, where they
/// meet. Parallel lines give `p1`.
pub(crate) fn closest_point(
    p1: &Vector3<f64>,
    w1: &Vector3<f64>,
    p2: &Vector3<f64>,
    w2: &Vector3<f64>,
) -> Vector3<f64> {
    let k = w1.dot(w2);
    let d = p2 - p1;
    let denominator = 1.0 - k * k;
    if denominator.abs() < 1e-15 {
        return *p1;
    }
    let s = (w1.dot(&d) - k * w2.dot(&d)) / denominator;
    p1 + w1 * s
}
