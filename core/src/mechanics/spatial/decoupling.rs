//! Which closed-form decoupling a six-joint arm allows, decided at compile time from its exact
//! geometry at `q = 0`: its joint axes, the tool pose there, and the point the decoupling turns
//! on (the run-time crate's `SpatialIk` solves with them).
//!
//! Where the geometry is rational (lengths rational, twists multiples of `pi/2`), parallel and
//! meeting axes are decided exactly. Where a named constant enters (a twist of 0.3 rad, an axis
//! `(1, 1, 0)`), its `f64` value is used and "parallel" and "meeting" mean within 1e-12 (of the
//! arm's scale). An arm with run-time lengths is classified at run time instead.

use num_traits::Zero;

use super::frames::{at_zero, SpatialKinematics};
use super::spec::SpatialArmSpec;
use crate::algebra::poly::Poly;
use crate::algebra::ring::{to_f64, Rational};
use crate::mechanics::planar::JointKind;

/// The classes of the run-time crate's `IkClass`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decoupling {
    /// Axes 2 and 3 parallel, axes 4-6 meeting.
    SphericalWrist,
    /// Joint 3 prismatic, axes 1 and 2 meeting, axes 4-6 meeting.
    SlidingWrist,
    /// Axes 2-4 parallel, axes 5 and 6 meeting.
    ParallelTriple,
}

/// The geometry a closed form needs, in `f64`.
#[derive(Clone, Debug, PartialEq)]
pub struct DecoupledGeometry {
    /// The class.
    pub class: Decoupling,
    /// A point on each axis at `q = 0`.
    pub points: [[f64; 3]; 6],
    /// Each unit axis at `q = 0`.
    pub axes: [[f64; 3]; 6],
    /// The tool's rotation (row-major) and position at `q = 0`.
    pub home: ([[f64; 3]; 3], [f64; 3]),
    /// The point the decoupling turns on.
    pub centre: [f64; 3],
    /// The largest distance of those points from the base.
    pub scale: f64,
}

/// Scalars the tests below run on: exact rationals, or `f64` within a tolerance.
trait Scalar: Clone {
    fn sub(&self, o: &Self) -> Self;
    fn add(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn div(&self, o: &Self) -> Self;
    fn negligible(&self, scale: f64) -> bool;
    fn to_f64(&self) -> f64;
}

impl Scalar for Rational {
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn div(&self, o: &Self) -> Self {
        self / o
    }
    fn negligible(&self, _scale: f64) -> bool {
        self.is_zero()
    }
    fn to_f64(&self) -> f64 {
        to_f64(self).unwrap_or(f64::NAN)
    }
}

impl Scalar for f64 {
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn div(&self, o: &Self) -> Self {
        self / o
    }
    fn negligible(&self, scale: f64) -> bool {
        self.abs() <= 1e-12 * scale.max(1.0)
    }
    fn to_f64(&self) -> f64 {
        *self
    }
}

type V<S> = [S; 3];

fn sub<S: Scalar>(a: &V<S>, b: &V<S>) -> V<S> {
    core::array::from_fn(|i| a[i].sub(&b[i]))
}
fn dot<S: Scalar>(a: &V<S>, b: &V<S>) -> S {
    a[0].mul(&b[0]).add(&a[1].mul(&b[1])).add(&a[2].mul(&b[2]))
}
fn cross<S: Scalar>(a: &V<S>, b: &V<S>) -> V<S> {
    core::array::from_fn(|i| {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        a[j].mul(&b[k]).sub(&a[k].mul(&b[j]))
    })
}
fn zero_vector<S: Scalar>(v: &V<S>, scale: f64) -> bool {
    v.iter().all(|x| x.negligible(scale))
}

/// Lines `(p, u)` and `(q, w)`, unit directions.
fn parallel<S: Scalar>(u: &V<S>, w: &V<S>) -> bool {
    zero_vector(&cross(u, w), 1.0)
}

/// Where two non-parallel lines meet, if they do.
fn meet<S: Scalar>(p: &V<S>, u: &V<S>, q: &V<S>, w: &V<S>, scale: f64) -> Option<V<S>> {
    if parallel(u, w) {
        return None;
    }
    let n = cross(u, w);
    let d = sub(q, p);
    // Coplanar: (q - p) . (u x w) = 0.
    if !dot(&d, &n).negligible(scale) {
        return None;
    }
    // p + s u with s = ((q - p) x w) . n / |n|^2.
    let s = dot(&cross(&d, w), &n).div(&dot(&n, &n));
    Some(core::array::from_fn(|i| p[i].add(&u[i].mul(&s))))
}

/// Distance test of point `c` from line `(p, u)`.
fn on_line<S: Scalar>(c: &V<S>, p: &V<S>, u: &V<S>, scale: f64) -> bool {
    zero_vector(&cross(&sub(c, p), u), scale)
}

/// The class of the arm, and its geometry, from the points and unit directions of its axes at
/// `q = 0`.
fn classify<S: Scalar>(
    kinds: &[JointKind],
    points: &[V<S>; 6],
    axes: &[V<S>; 6],
    scale: f64,
) -> Option<(Decoupling, V<S>)> {
    let revolute = |r: core::ops::Range<usize>| kinds[r].iter().all(|k| *k == JointKind::Revolute);
    let wrist = || {
        let c = meet(&points[3], &axes[3], &points[4], &axes[4], scale)?;
        (on_line(&c, &points[5], &axes[5], scale) && !parallel(&axes[4], &axes[5])).then_some(c)
    };
    if revolute(0..6) && parallel(&axes[1], &axes[2]) && !parallel(&axes[0], &axes[1]) {
        if let Some(c) = wrist() {
            return Some((Decoupling::SphericalWrist, c));
        }
        if parallel(&axes[1], &axes[3]) && !parallel(&axes[4], &axes[1]) {
            if let Some(c) = meet(&points[4], &axes[4], &points[5], &axes[5], scale) {
                return Some((Decoupling::ParallelTriple, c));
            }
        }
    }
    let sliding = revolute(0..2)
        && kinds[2] == JointKind::Prismatic
        && revolute(3..6)
        && meet(&points[0], &axes[0], &points[1], &axes[1], scale).is_some();
    if sliding {
        return wrist().map(|c| (Decoupling::SlidingWrist, c));
    }
    None
}

/// The closed-form geometry of a six-joint arm whose values are all known at compile time, if
/// its class is one of [`Decoupling`]'s.
#[must_use]
pub fn decouple(arm: &SpatialArmSpec) -> Option<DecoupledGeometry> {
    if arm.joints.len() != 6 {
        return None;
    }
    let kinematics = &SpatialKinematics::home(arm);
    let zero = |e| at_zero(e);
    let points: Vec<[Poly; 3]> = kinematics
        .axes
        .iter()
        .map(|(o, _)| o.each_ref().map(zero))
        .collect();
    let axes: Vec<[Poly; 3]> = kinematics
        .axes
        .iter()
        .map(|(_, z)| z.each_ref().map(zero))
        .collect();
    let home_r: [[Poly; 3]; 3] = kinematics
        .tool
        .r
        .each_ref()
        .map(|row| row.each_ref().map(zero));
    let home_p: [Poly; 3] = kinematics.tool.p.each_ref().map(zero);
    let all: Vec<&Poly> = points
        .iter()
        .chain(&axes)
        .flatten()
        .chain(home_p.iter())
        .collect();
    // Run-time lengths: decided at run time.
    if all
        .iter()
        .any(|p| p.params().iter().any(|q| q.value().is_none()))
    {
        return None;
    }
    let kinds: Vec<JointKind> = arm.joints.iter().map(|j| j.kind).collect();
    let f64s = |v: &[Poly; 3]| {
        v.each_ref()
            .map(|p| p.eval(&|q| q.value().unwrap_or(f64::NAN)))
    };
    let points_f: [V<f64>; 6] = core::array::from_fn(|i| f64s(&points[i]));
    let axes_f: [V<f64>; 6] = core::array::from_fn(|i| f64s(&axes[i]));
    let scale = points_f
        .iter()
        .chain(core::iter::once(&f64s(&home_p)))
        .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
        .fold(f64::MIN_POSITIVE, f64::max);
    let rational: Option<Vec<[Rational; 3]>> = points
        .iter()
        .chain(&axes)
        .map(|v| {
            Some([
                v[0].as_rational()?,
                v[1].as_rational()?,
                v[2].as_rational()?,
            ])
        })
        .collect();
    let (class, centre) = match rational {
        Some(r) => {
            let points_r: [V<Rational>; 6] = core::array::from_fn(|i| r[i].clone());
            let axes_r: [V<Rational>; 6] = core::array::from_fn(|i| r[6 + i].clone());
            let (class, c) = classify(&kinds, &points_r, &axes_r, scale)?;
            (class, c.map(|x| x.to_f64()))
        }
        None => classify(&kinds, &points_f, &axes_f, scale)?,
    };
    Some(DecoupledGeometry {
        class,
        points: points_f,
        axes: axes_f,
        home: (
            home_r.each_ref().map(|row| {
                row.each_ref()
                    .map(|p| p.eval(&|q| q.value().unwrap_or(f64::NAN)))
            }),
            f64s(&home_p),
        ),
        centre,
        scale,
    })
}
