//! The three classes' solutions, stage by stage: each stage hands the next its angles as turns
//! (cosine and sine), and each position solution undoes joints 1-3 on the two vectors the wrist
//! reads, not on a whole rotation.

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use core::f64::consts::PI;

use nalgebra::{SVector, Vector3};

use super::position::{Elbow, Shoulder};
use super::solver::{any_across, closest_point, Goal, Miss, SpatialIk};
use super::subproblems::{about, angle_and_turn, AxisPair, Turn};
use super::wrist::Wrist;
use super::IkSolutions;

/// Marks `out` singular if `singular`; the miss (or, with none, `otherwise`) if nothing was
/// found.
fn finish(
    out: &mut IkSolutions<6>,
    singular: bool,
    miss: Option<Miss>,
    otherwise: Option<Miss>,
) -> Result<(), Miss> {
    if singular {
        out.mark_singular();
    }
    match (out.is_empty(), miss.or(otherwise)) {
        (true, Some(m)) => Err(m),
        _ => Ok(()),
    }
}

impl SpatialIk {
    pub(crate) fn spherical(&self, goal: &Goal, out: &mut IkSolutions<6>) -> Result<(), Miss> {
        let mut singular = false;
        let (w1, w2, w3) = (&self.axes[0], &self.axes[1], &self.axes[2]);
        let shoulder = Shoulder::new(self, w2, &goal.centre, &self.centre, &mut singular)?;
        let elbow = Elbow::new(self, &self.centre);
        let wrist = Wrist::new(&self.axes);
        let (rest_w6, rest_across) = wrist.targets(&goal.rest);
        let mut miss = None;
        for k in 0..2 {
            let undo1 = shoulder.turns[k].inverse();
            let (w6_1, across_1) = (undo1.rotate(w1, &rest_w6), undo1.rotate(w1, &rest_across));
            let bends = match elbow.solve(&shoulder.back(k), &mut singular) {
                Ok(bends) => bends,
                Err(e) => {
                    miss = Some(e);
                    continue;
                }
            };
            for bend in bends {
                let undo = |v: &Vector3<f64>| {
                    let v = bend.turn2.inverse().rotate(w2, v);
                    bend.turn3.inverse().rotate(w3, &v)
                };
                let Some(wrists) = wrist.solve(&undo(&w6_1), &undo(&across_1), &mut singular)
                else {
                    continue;
                };
                for [t4, t5, t6] in wrists {
                    let t1 = shoulder.angles[k];
                    out.push(SVector::from([t1, bend.t2, bend.t3, t4, t5, t6]));
                }
            }
        }
        let orientation = Miss::radians("the wrist's orientation", 0.0);
        finish(out, singular, miss, Some(orientation))
    }

    pub(crate) fn sliding(&self, goal: &Goal, out: &mut IkSolutions<6>) -> Result<(), Miss> {
        let (w1, w2, w3) = (&self.axes[0], &self.axes[1], &self.axes[2]);
        let shoulder = closest_point(&self.points[0], w1, &self.points[1], w2);
        let a = self.centre - shoulder;
        let q = goal.centre - shoulder;
        let reach2 = q.norm_squared();
        // |a + d w3|^2 = reach^2
        let half_b = a.dot(w3);
        let disc = half_b * half_b - a.norm_squared() + reach2;
        let slack = self.slack() * self.scale.max(f64::MIN_POSITIVE);
        if disc < -slack {
            let closest = (a.norm_squared() - half_b * half_b).max(0.0).sqrt();
            return Err(Miss::metres("the wrist centre", closest - reach2.sqrt()));
        }
        let root = disc.max(0.0).sqrt();
        let pair = AxisPair::new(w1, w2);
        let wrist = Wrist::new(&self.axes);
        let (rest_w6, rest_across) = wrist.targets(&goal.rest);
        let (mut singular, mut miss) = (false, None);
        for d in [-half_b + root, -half_b - root] {
            let p = a + w3 * d;
            let zs = match pair.meet(w2.dot(&p), &q, slack) {
                Ok(zs) => zs,
                Err(by) => {
                    miss = Some(Miss::metres("the wrist centre", by.sqrt()));
                    continue;
                }
            };
            for z in zs {
                let (t2, turn2) = angle_and_turn(about(w2, &p, &z));
                let (t1, turn1) = angle_and_turn(about(w1, &z, &q));
                let undo = |v: &Vector3<f64>| {
                    let v = turn1.inverse().rotate(w1, v);
                    turn2.inverse().rotate(w2, &v)
                };
                let Some(wrists) = wrist.solve(&undo(&rest_w6), &undo(&rest_across), &mut singular)
                else {
                    continue;
                };
                for [t4, t5, t6] in wrists {
                    out.push(SVector::from([t1, t2, d, t4, t5, t6]));
                }
            }
        }
        let orientation = Miss::radians("the wrist's orientation", 0.0);
        finish(out, singular, miss, Some(orientation))
    }

    pub(crate) fn parallel(&self, goal: &Goal, out: &mut IkSolutions<6>) -> Result<(), Miss> {
        let mut singular = false;
        let u = self.axes[1];
        let signs = [1usize, 2, 3].map(|i| {
            if self.axes[i].dot(&u) > 0.0 {
                1.0
            } else {
                -1.0
            }
        });
        let shoulder = Shoulder::new(self, &u, &goal.centre, &self.centre, &mut singular)?;
        let elbow = Elbow::new(self, &self.points[3]);
        let last = LastTwo::new(&self.axes);
        let arm = self.centre - self.points[3];
        let mut miss = None;
        for k in 0..2 {
            let Some(orients) = last.solve(goal, shoulder.turns[k], &mut singular, &mut miss)
            else {
                continue;
            };
            let back = shoulder.back(k);
            for o in orients {
                // The point on axis 4, where joints 2 and 3 must put it.
                let wanted = back - o.turn.rotate(&u, &arm);
                match elbow.solve(&wanted, &mut singular) {
                    Ok(bends) => {
                        for b in bends {
                            let t4 = signs[2] * (o.theta - signs[0] * b.t2 - signs[1] * b.t3);
                            let t1 = shoulder.angles[k];
                            out.push(SVector::from([t1, b.t2, b.t3, t4, o.t5, o.t6]));
                        }
                    }
                    Err(e) => miss = Some(e),
                }
            }
        }
        finish(out, singular, miss, None)
    }
}

/// Joints 5 and 6 of the parallel class, and the angle `theta` the parallel axes 2-4 turn in
/// all: `R(u, theta) R(w5, t5) R(w6, t6) = N = R(w1, -t1) rest`. `R(u, theta) R(w5, t5)` takes
/// `w6` to `N w6`: two rotations about meeting axes, as in a spherical wrist, solved in the
/// same stable form (a singular wrist keeps `R(w5, t5) w6` on `u` to rounding, not to its
/// square root, so that it is recognised).
struct LastTwo {
    w1: Vector3<f64>,
    u: Vector3<f64>,
    w5: Vector3<f64>,
    w6: Vector3<f64>,
    pair: AxisPair,
    /// `w5 . w6`, which rotations about axis 5 keep.
    b: f64,
    /// `w6` across axis 5, and `w5 x w6`: the `(cos, sin)` of axis 5's angle taking `w6` to `z`
    /// are their dot products with `z`.
    six_across: Vector3<f64>,
    five_x_six: Vector3<f64>,
    /// A unit vector across `u`, and `u` crossed with it: `theta` is read from them.
    across: Vector3<f64>,
    across_turned: Vector3<f64>,
    flips: bool,
}

/// One `(t5, t6, theta)`, with `theta`'s turn.
#[derive(Clone, Copy)]
struct Orientation {
    t5: f64,
    t6: f64,
    theta: f64,
    turn: Turn,
}

impl LastTwo {
    fn new(axes: &[Vector3<f64>; 6]) -> Self {
        let (u, w5, w6) = (axes[1], axes[4], axes[5]);
        let across = any_across(&u);
        Self {
            w1: axes[0],
            u,
            w5,
            w6,
            pair: AxisPair::new(&u, &w5),
            b: w5.dot(&w6),
            six_across: w6 - w5 * w5.dot(&w6),
            five_x_six: w5.cross(&w6),
            across,
            across_turned: u.cross(&across),
            // (theta + pi, -t5, t6 + pi) is a second solution when u is across w5 and w6 =
            // +-u: as for a spherical wrist (`Wrist::new`), u in the place of w4 (the UR
            // family's).
            flips: u.dot(&w5).abs() <= 1e-14 && u.cross(&w6).norm() <= 1e-14,
        }
    }

    /// How far `u . N w6` lies beyond what `R(w5, t5) w6` can give it.
    fn beyond(&self, n_w6: &Vector3<f64>) -> f64 {
        let (u, w5, w6) = (&self.u, &self.w5, &self.w6);
        let (a, b) = (u.dot(&self.six_across), u.dot(&w5.cross(w6)));
        let c = u.dot(n_w6) - u.dot(w5) * w5.dot(w6);
        c.abs() - (a * a + b * b).sqrt()
    }

    /// Both orientations for joint 1's turn `turn1`; `None` (and `miss` set) when the tool axis
    /// cannot be placed.
    fn solve(
        &self,
        goal: &Goal,
        turn1: Turn,
        singular: &mut bool,
        miss: &mut Option<Miss>,
    ) -> Option<[Orientation; 2]> {
        let (u, w1) = (&self.u, &self.w1);
        let n = |v: &Vector3<f64>| turn1.inverse().rotate(w1, &(goal.rest * v));
        let n_t_u = goal.rest.transpose() * turn1.rotate(w1, u);
        let n_w6 = n(&self.w6);
        let Ok(zs) = self.pair.meet(self.b, &n_w6, 1e-12) else {
            *miss = Some(Miss::radians("the tool axis", self.beyond(&n_w6)));
            return None;
        };
        let one = |z: &Vector3<f64>, singular: &mut bool| {
            let (t5, turn5) = angle_and_turn((self.six_across.dot(z), self.five_x_six.dot(z)));
            // On the singularity z lies along u (w6 after joint 5 is parallel to axes 2-4):
            // t6 is free and 0 represents it.
            let free = (z - u * u.dot(z)).norm_squared() < 1e-18;
            *singular |= free;
            let (t6, undo6) = if free {
                (0.0, Turn::ZERO)
            } else {
                // R(w6, -t6) (R5^T u) = N^T u
                let from = turn5.inverse().rotate(&self.w5, u);
                let (t, turn) = angle_and_turn(about(&self.w6, &from, &n_t_u));
                (-t, turn)
            };
            // R(u, theta) = N R6^T R5^T on a vector across u.
            let v = turn5.inverse().rotate(&self.w5, &self.across);
            let seen = n(&undo6.rotate(&self.w6, &v));
            let (theta, turn) =
                angle_and_turn((self.across.dot(&seen), self.across_turned.dot(&seen)));
            (
                Orientation {
                    t5,
                    t6,
                    theta,
                    turn,
                },
                free,
            )
        };
        let (first, free) = one(&zs[0], singular);
        // At the singularity both keep t6 = 0 (the family's representative); the flip would
        // make it pi.
        let second = if self.flips && !free {
            Orientation {
                t5: -first.t5,
                t6: first.t6 + PI,
                theta: first.theta + PI,
                turn: first.turn.opposite(),
            }
        } else {
            one(&zs[1], singular).0
        };
        Some([first, second])
    }
}
