//! Desired motions: quintic point-to-point, via-points, a straight line of the tip.

use core::cell::Cell;

use nalgebra::{Point2, SMatrix, SVector, Vector2, Vector3};

use super::error::{finite, positive};
use super::SimError;
use crate::kinematics::{DlsOptions, IkTarget};
use crate::{Jet, PlanarArm};

/// Desired angles, rates and accelerations at one time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample<const N: usize> {
    /// Joint angles, rad.
    pub q: SVector<f64, N>,
    /// Joint rates, rad/s.
    pub qd: SVector<f64, N>,
    /// Joint accelerations, rad/s^2.
    pub qdd: SVector<f64, N>,
}

impl<const N: usize> Sample<N> {
    /// At rest at `q`.
    #[must_use]
    pub fn rest(q: SVector<f64, N>) -> Self {
        Self {
            q,
            qd: SVector::zeros(),
            qdd: SVector::zeros(),
        }
    }
}

/// A desired joint motion from `t = 0` to [`duration`](Self::duration).
///
/// Before 0 it is the start sample and after the end the end sample, unchanged (at rest for a
/// rest-to-rest motion). A NaN time gives a NaN sample.
///
/// # Example
/// A trajectory of one's own, to hand to a controller: a sinusoid on the elbow.
/// ```
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::sim::{Sample, Trajectory};
///
/// struct Wave;
///
/// impl Trajectory<2> for Wave {
///     fn sample(&self, t: f64) -> Sample<2> {
///         let (s, c) = (2.0 * t).sin_cos();
///         Sample {
///             q: Vector2::new(0.0, 0.5 * s),
///             qd: Vector2::new(0.0, c),
///             qdd: Vector2::new(0.0, -2.0 * s),
///         }
///     }
///     fn duration(&self) -> f64 {
///         f64::INFINITY
///     }
/// }
///
/// assert_eq!(Wave.sample(0.0).qd, Vector2::new(0.0, 1.0));
/// ```
pub trait Trajectory<const N: usize> {
    /// Angles, rates and accelerations at `t` (s).
    fn sample(&self, t: f64) -> Sample<N>;
    /// The time the motion takes, s.
    fn duration(&self) -> f64;
}

impl<T: Trajectory<N> + ?Sized, const N: usize> Trajectory<N> for &T {
    fn sample(&self, t: f64) -> Sample<N> {
        (**self).sample(t)
    }
    fn duration(&self) -> f64 {
        (**self).duration()
    }
}

/// A quintic polynomial in time per joint: position, velocity and acceleration given at both
/// ends, so that a chain of them is continuous in all three. Rest to rest, it is the
/// minimum-jerk motion `q0 + (q1 - q0) (10 s^3 - 15 s^4 + 6 s^5)`, `s = t / T`.
///
/// # Example
/// ```
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::sim::{Quintic, Trajectory};
///
/// let path = Quintic::rest_to_rest(Vector2::new(0.0, 1.0), Vector2::new(1.0, -1.0), 2.0)?;
/// let mid = path.sample(1.0);
/// assert!((mid.q - Vector2::new(0.5, 0.0)).norm() < 1e-15); // symmetric
/// assert!((mid.qd[0] - 15.0 / 16.0).abs() < 1e-15); // peak rate 15/8 of the mean
/// assert_eq!(path.sample(2.0).qd, Vector2::zeros());
/// assert!(Quintic::rest_to_rest(Vector2::zeros(), Vector2::zeros(), 0.0).is_err());
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quintic<const N: usize> {
    duration: f64,
    /// Coefficients of `s^0 .. s^5` in the normalised time `s = t / duration`.
    c: [SVector<f64, N>; 6],
    start: Sample<N>,
    end: Sample<N>,
}

impl<const N: usize> Quintic<N> {
    /// From `start` at `t = 0` to `end` at `t = duration`.
    ///
    /// # Errors
    /// [`SimError::BadArgument`] for a duration that is not positive and finite,
    /// [`SimError::NonFinite`] for a non-finite sample.
    pub fn new(start: Sample<N>, end: Sample<N>, duration: f64) -> Result<Self, SimError> {
        let t = positive(duration, "duration")?;
        for (v, name) in [
            (&start.q, "start q"),
            (&start.qd, "start qd"),
            (&start.qdd, "start qdd"),
            (&end.q, "end q"),
            (&end.qd, "end qd"),
            (&end.qdd, "end qdd"),
        ] {
            finite(v, name)?;
        }
        // In s = t / T the end conditions are p, T v, T^2 a.
        let (p0, v0, a0) = (start.q, start.qd * t, start.qdd * (t * t));
        let (p1, v1, a1) = (end.q, end.qd * t, end.qdd * (t * t));
        let d = p1 - p0;
        let c = [
            p0,
            v0,
            a0 * 0.5,
            d * 10.0 - v0 * 6.0 - v1 * 4.0 - a0 * 1.5 + a1 * 0.5,
            d * -15.0 + v0 * 8.0 + v1 * 7.0 + a0 * 1.5 - a1,
            d * 6.0 - (v0 + v1) * 3.0 - a0 * 0.5 + a1 * 0.5,
        ];
        Ok(Self {
            duration: t,
            c,
            start,
            end,
        })
    }

    /// From rest at `q0` to rest at `q1` in `duration` seconds.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub fn rest_to_rest(
        q0: SVector<f64, N>,
        q1: SVector<f64, N>,
        duration: f64,
    ) -> Result<Self, SimError> {
        Self::new(Sample::rest(q0), Sample::rest(q1), duration)
    }

    /// The sample at `t = 0`.
    #[must_use]
    pub fn start(&self) -> Sample<N> {
        self.start
    }

    /// The sample at the end.
    #[must_use]
    pub fn end(&self) -> Sample<N> {
        self.end
    }
}

impl<const N: usize> Trajectory<N> for Quintic<N> {
    fn sample(&self, t: f64) -> Sample<N> {
        if t <= 0.0 {
            return self.start;
        }
        if t >= self.duration {
            return self.end;
        }
        if t.is_nan() {
            return nan_sample();
        }
        let s = t / self.duration;
        let c = &self.c;
        let q = c[0] + (c[1] + (c[2] + (c[3] + (c[4] + c[5] * s) * s) * s) * s) * s;
        let ds = c[1] + (c[2] * 2.0 + (c[3] * 3.0 + (c[4] * 4.0 + c[5] * (5.0 * s)) * s) * s) * s;
        let dds = c[2] * 2.0 + (c[3] * 6.0 + (c[4] * 12.0 + c[5] * (20.0 * s)) * s) * s;
        Sample {
            q,
            qd: ds / self.duration,
            qdd: dds / (self.duration * self.duration),
        }
    }

    fn duration(&self) -> f64 {
        self.duration
    }
}

fn nan_sample<const N: usize>() -> Sample<N> {
    let nan = SVector::from_element(f64::NAN);
    Sample {
        q: nan,
        qd: nan,
        qdd: nan,
    }
}

/// Through `K` via-points at given times: one [`Quintic`] per interval, so position, velocity
/// and acceleration are continuous (the jerk jumps at the via-points). Starts and ends at rest.
///
/// At an interior via-point the velocity of each joint is the average of the slopes of the two
/// intervals beside it (weighted by the other's duration, which is exact for a quadratic), or
/// zero where the two slopes differ in sign (so the joint stops there rather than overshoots);
/// the acceleration is the change of slope over the mean of the two durations.
///
/// # Example
/// ```
/// use planar_arm::nalgebra::Vector2;
/// use planar_arm::sim::{Trajectory, ViaPoints};
///
/// let points = [Vector2::new(0.0, 0.0), Vector2::new(1.0, 0.5), Vector2::new(1.5, -0.5)];
/// let path = ViaPoints::new([0.0, 1.0, 3.0], points)?;
/// assert_eq!(path.sample(1.0).q, points[1]);
/// assert!(path.sample(1.0).qd[0] > 0.0); // passes through, does not stop
/// assert_eq!(path.sample(3.0).qd, Vector2::zeros());
/// assert!(ViaPoints::new([0.0, 0.0, 1.0], points).is_err()); // times must increase
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViaPoints<const N: usize, const K: usize> {
    times: [f64; K],
    knots: [Sample<N>; K],
}

impl<const N: usize, const K: usize> ViaPoints<N, K> {
    /// Through `points[i]` at `times[i]`, from rest to rest; the motion runs from `times[0]`
    /// (which may differ from 0: it is then at rest at `points[0]` before).
    ///
    /// # Errors
    /// [`SimError::BadArgument`] when `K < 2`, or the times are not finite and strictly
    /// increasing; [`SimError::NonFinite`] for a non-finite point.
    pub fn new(times: [f64; K], points: [SVector<f64, N>; K]) -> Result<Self, SimError> {
        if K < 2 {
            return Err(SimError::BadArgument {
                argument: "via-points (at least 2)",
                value: K as f64,
            });
        }
        for (i, t) in times.iter().enumerate() {
            let increasing = i == 0 || *t > times[i - 1];
            if !t.is_finite() || !increasing {
                return Err(SimError::BadArgument {
                    argument: "times",
                    value: *t,
                });
            }
        }
        for p in &points {
            finite(p, "points")?;
        }
        let mut knots = points.map(Sample::rest);
        for i in 1..K - 1 {
            let (h0, h1) = (times[i] - times[i - 1], times[i + 1] - times[i]);
            let s0 = (points[i] - points[i - 1]) / h0;
            let s1 = (points[i + 1] - points[i]) / h1;
            for j in 0..N {
                knots[i].qd[j] = if s0[j] * s1[j] > 0.0 {
                    (h1 * s0[j] + h0 * s1[j]) / (h0 + h1)
                } else {
                    0.0
                };
                knots[i].qdd[j] = 2.0 * (s1[j] - s0[j]) / (h0 + h1);
            }
        }
        Ok(Self { times, knots })
    }

    /// The via-points with the velocities and accelerations chosen there.
    #[must_use]
    pub fn knots(&self) -> &[Sample<N>; K] {
        &self.knots
    }
}

impl<const N: usize, const K: usize> Trajectory<N> for ViaPoints<N, K> {
    fn sample(&self, t: f64) -> Sample<N> {
        if t.is_nan() {
            return nan_sample();
        }
        // The interval holding t (the first at or before the start, the last after the end).
        let i = self.times[1..K - 1]
            .iter()
            .take_while(|&&ti| ti <= t)
            .count();
        let t0 = self.times[i];
        // A quintic of two finite samples and a positive duration: it cannot fail.
        match Quintic::new(self.knots[i], self.knots[i + 1], self.times[i + 1] - t0) {
            Ok(piece) => piece.sample(t - t0),
            Err(_) => nan_sample(),
        }
    }

    fn duration(&self) -> f64 {
        self.times[K - 1]
    }
}

/// The tip along a straight line at a minimum-jerk pace (rest to rest), the joint angles found
/// by inverse kinematics ([`PlanarArm::inverse_kinematics_near`]) seeded from the previous
/// sample, the rates and accelerations from the Jacobian.
///
/// For two links the tip position fixes the angles. For three links and more the last link's
/// absolute angle is held at its start value too (a pose target: square for three links, so
/// the angles are again a function of time; for more than three the extra freedom is resolved
/// by the minimum-norm rate and the nearest solution, which agree to first order only).
/// `new` samples the whole path and fails if any point of it is out of reach or singular.
///
/// # Example
/// ```
/// use planar_arm::prelude::*;
/// use planar_arm::sim::{TipLine, Trajectory};
///
/// #[derive(PlanarArm, Default)]
/// #[arm(gravity = 9.81)]
/// struct Rods {
///     #[arm(length = 1, mass = 1)]
///     upper: Revolute,
///     #[arm(length = 1, mass = 1)]
///     fore: Revolute,
/// }
///
/// let arm = Rods::default();
/// let q0 = Vector2::new(-0.5, 1.5);
/// let line = TipLine::new(&arm, q0, Point2::new(0.2, 1.4), 1.5)?;
/// let start = arm.tip_pose(&q0).translation.vector;
/// let mid = arm.tip_pose(&line.sample(0.75).q).translation.vector;
/// assert!((mid - (start + Vector2::new(0.2, 1.4)) / 2.0).norm() < 1e-9);
/// assert!(TipLine::new(&arm, q0, Point2::new(5.0, 0.0), 1.0).is_err()); // out of reach
/// # Ok::<(), planar_arm::sim::SimError>(())
/// ```
#[derive(Debug, Clone)]
pub struct TipLine<'a, A: ?Sized, const N: usize> {
    arm: &'a A,
    from: Vector2<f64>,
    to: Vector2<f64>,
    angle: f64,
    duration: f64,
    start: SVector<f64, N>,
    /// The last solution and its time: the seed of the next inverse kinematics.
    last: Cell<(f64, SVector<f64, N>)>,
}

/// Points at which [`TipLine::new`] checks the path.
const CHECKS: u32 = 64;
/// Below this manipulability the path counts as singular.
const SINGULAR: f64 = 1e-6;

impl<'a, A: PlanarArm<N> + ?Sized, const N: usize> TipLine<'a, A, N> {
    /// From the tip at `q0` to `to` in `duration` seconds, rest to rest.
    ///
    /// # Errors
    /// [`SimError::BadArgument`] for a bad duration, [`SimError::NonFinite`] for non-finite
    /// input, and [`SimError::Arm`] with the inverse kinematics' error (or
    /// [`ArmError::Singular`](crate::ArmError::Singular)) when a point of the line cannot be
    /// reached.
    pub fn new(
        arm: &'a A,
        q0: SVector<f64, N>,
        to: Point2<f64>,
        duration: f64,
    ) -> Result<Self, SimError> {
        positive(duration, "duration")?;
        finite(&q0, "q0")?;
        if !(to.x.is_finite() && to.y.is_finite()) {
            return Err(SimError::NonFinite {
                argument: "to",
                t: f64::NAN,
            });
        }
        let pose = arm.tip_pose(&q0);
        let line = Self {
            arm,
            from: pose.translation.vector,
            to: to.coords,
            angle: pose.rotation.angle(),
            duration,
            start: q0,
            last: Cell::new((0.0, q0)),
        };
        for k in 0..=CHECKS {
            let t = duration * f64::from(k) / f64::from(CHECKS);
            let q = line.solve(t)?;
            let measure = arm.manipulability(&q);
            if measure.is_nan() || measure <= SINGULAR {
                return Err(crate::ArmError::Singular {
                    measure,
                    threshold: SINGULAR,
                }
                .into());
            }
        }
        line.last.set((0.0, q0));
        Ok(line)
    }

    /// The minimum-jerk progress along the line: (s, ds/dt, d2s/dt2), s from 0 to 1.
    fn progress(&self, t: f64) -> (f64, f64, f64) {
        let u = (t / self.duration).clamp(0.0, 1.0);
        let (t1, t2) = (self.duration, self.duration * self.duration);
        let s = u * u * u * (10.0 - 15.0 * u + 6.0 * u * u);
        let ds = 30.0 * u * u * (1.0 - u) * (1.0 - u) / t1;
        let dds = 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u) / t2;
        (s, ds, dds)
    }

    /// The angles at `t`, by inverse kinematics from the last solution.
    fn solve(&self, t: f64) -> Result<SVector<f64, N>, SimError> {
        let (s, _, _) = self.progress(t);
        let point = Point2::from(self.from + (self.to - self.from) * s);
        let target = if N <= 2 {
            IkTarget::Position(point)
        } else {
            IkTarget::Pose(nalgebra::Isometry2::new(point.coords, self.angle))
        };
        let options = DlsOptions {
            max_iterations: 500,
            tolerance: 1e-12,
            ..DlsOptions::default()
        };
        let (_, seed) = self.last.get();
        let seed = if seed.iter().all(|x| x.is_finite()) {
            seed
        } else {
            self.start
        };
        let q = self.arm.inverse_kinematics_near(&target, &seed, &options)?;
        self.last.set((t, q));
        Ok(q)
    }

    /// The task rows the line controls: tip x and y, and the last link's angle beyond 2 links.
    fn rows(&self) -> usize {
        if N <= 2 {
            2
        } else {
            3
        }
    }

    /// The joint rates for the task rate `xd` (minimum norm when the task has fewer rows).
    fn resolve(&self, j: &SMatrix<f64, 3, N>, xd: &Vector3<f64>) -> SVector<f64, N> {
        let rows = self.rows();
        let mut jt = *j;
        let mut x = *xd;
        for r in rows..3 {
            jt.row_mut(r).fill(0.0);
            x[r] = 0.0;
        }
        // J^+ x = J^T (J J^T)^-1 x on the task rows; rank-deficient rows were zeroed above and
        // get a unit diagonal so that the factorisation exists.
        let mut jjt = jt * jt.transpose();
        for r in rows..3 {
            jjt[(r, r)] = 1.0;
        }
        match jjt.cholesky() {
            Some(c) => jt.tr_mul(&c.solve(&x)),
            None => SVector::from_element(f64::NAN),
        }
    }
}

impl<A: PlanarArm<N> + ?Sized, const N: usize> Trajectory<N> for TipLine<'_, A, N> {
    /// The sample at `t`: NaN if the inverse kinematics fails there (it succeeded at the 65
    /// points `new` checked).
    fn sample(&self, t: f64) -> Sample<N> {
        if t.is_nan() {
            return nan_sample();
        }
        let Ok(q) = self.solve(t) else {
            return nan_sample();
        };
        let (_, ds, dds) = self.progress(t);
        let dir = self.to - self.from;
        let j = self.arm.jacobian(&q);
        let qd = self.resolve(&j, &Vector3::new(dir.x * ds, dir.y * ds, 0.0));
        // Jdot qd: the Jacobian in jets seeded along qd.
        let qj = SVector::<Jet<1>, N>::from_fn(|i, _| Jet {
            re: q[i],
            eps: [qd[i]],
        });
        let jdot_qd = self.arm.jacobian(&qj).map(|x| x.eps[0]) * qd;
        let xdd = Vector3::new(dir.x * dds, dir.y * dds, 0.0) - jdot_qd;
        let qdd = self.resolve(&j, &xdd);
        Sample { q, qd, qdd }
    }

    fn duration(&self) -> f64 {
        self.duration
    }
}
