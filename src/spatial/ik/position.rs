//! The stages that place a point: joint 1 bringing it into the plane the parallel axes move in
//! ([`Shoulder`]), and two parallel axes carrying one point to another in that plane
//! ([`Elbow`]). Each is set up once per solve with what depends on the arm alone, then solved
//! for each candidate the stage before it left.

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::Vector3;

use super::atan2::atan2;
use super::solver::{Miss, SpatialIk};
use super::subproblems::{about, angle_and_turn, cos_sin, Trig, Turn};

/// The two joint-1 angles that bring a point into the plane through a given point across the
/// parallel axes' direction, and where each leaves the point (joint 1 undone).
pub(crate) struct Shoulder {
    pub angles: [f64; 2],
    pub turns: [Turn; 2],
    /// `point - r1` split along and across axis 1, and axis 1 crossed with it: `R(w1, -t1)`
    /// of it is `along + across cos t1 - w1_x_v sin t1`.
    along: Vector3<f64>,
    across: Vector3<f64>,
    w1_x_v: Vector3<f64>,
    r1: Vector3<f64>,
}

impl Shoulder {
    /// Joint 1 of `ik` for `point` (where the tracked point must go) into the plane through
    /// `on_plane` across `u`.
    pub fn new(
        ik: &SpatialIk,
        u: &Vector3<f64>,
        point: &Vector3<f64>,
        on_plane: &Vector3<f64>,
        singular: &mut bool,
    ) -> Result<Self, Miss> {
        let (r1, w1) = (ik.points[0], ik.axes[0]);
        let v = point - r1;
        let along = w1 * w1.dot(&v);
        let across = v - along;
        let w1_x_v = w1.cross(&v);
        // u . (r1 + R(w1, -t) v) = u . on_plane
        let a = u.dot(&across);
        let b = -u.dot(&w1_x_v);
        let c = u.dot(&(on_plane - r1)) - u.dot(&along);
        let (angles, turns) = match cos_sin(a, b, c, ik.slack()) {
            Trig::Two(roots) => (roots.angles(roots.phi()), roots.turns()),
            Trig::Any => {
                *singular = true;
                ([0.0; 2], [Turn::ZERO; 2])
            }
            Trig::None(by) => return Err(Miss::metres("the wrist centre's plane", by)),
        };
        Ok(Self {
            angles,
            turns,
            along,
            across,
            w1_x_v,
            r1,
        })
    }

    /// The point with joint 1's `k`-th angle undone.
    pub fn back(&self, k: usize) -> Vector3<f64> {
        let t = self.turns[k];
        self.r1 + self.along + self.across * t.c - self.w1_x_v * t.s
    }
}

/// One elbow solution: joints 2 and 3, as angles and as turns.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Bend {
    pub t2: f64,
    pub t3: f64,
    pub turn2: Turn,
    pub turn3: Turn,
}

/// Joints 2 and 3 (parallel axes) taking a fixed point `from` (at `q = 0`) to a point `to`,
/// both in one plane across the axes: `|e + R(w3, t3) v| = |to - c2|` gives `t3`, the rotation
/// about axis 2 that finishes the job `t2`.
pub(crate) struct Elbow {
    w2: Vector3<f64>,
    w3: Vector3<f64>,
    from: Vector3<f64>,
    /// The axes' points in the plane through `from`.
    c2: Vector3<f64>,
    /// From axis 3 to `from`, and from axis 2 to axis 3.
    v: Vector3<f64>,
    e: Vector3<f64>,
    /// `a cos t3 + b sin t3 = c`, `a` and `b` fixed, `phi = atan2(b, a)`.
    a: f64,
    b: f64,
    phi: f64,
    /// `(|e|^2 + |v|^2) / 2`, `|e|` and `|v|`.
    half_sum: f64,
    lengths: (f64, f64),
    slack: f64,
}

impl Elbow {
    pub fn new(ik: &SpatialIk, from: &Vector3<f64>) -> Self {
        let (w2, w3) = (ik.axes[1], ik.axes[2]);
        let on_plane = |r: &Vector3<f64>| r + w2 * w2.dot(&(from - r));
        let (c2, c3) = (on_plane(&ik.points[1]), on_plane(&ik.points[2]));
        let (v, e) = (from - c3, c3 - c2);
        let (a, b) = (e.dot(&v), e.dot(&w3.cross(&v)));
        let lengths = (e.norm(), v.norm());
        Self {
            w2,
            w3,
            from: *from,
            c2,
            v,
            e,
            a,
            b,
            phi: atan2(b, a),
            half_sum: 0.5 * (e.norm_squared() + v.norm_squared()),
            lengths,
            slack: ik.slack() * (lengths.0 + lengths.1),
        }
    }

    /// Both elbow solutions for `to` (equal on the boundary of the annulus).
    pub fn solve(&self, to: &Vector3<f64>, singular: &mut bool) -> Result<[Bend; 2], Miss> {
        let w2 = &self.w2;
        let d = to - w2 * w2.dot(&(to - self.from)) - self.c2;
        let delta2 = d.norm_squared();
        let (angles, turns) =
            match cos_sin(self.a, self.b, 0.5 * delta2 - self.half_sum, self.slack) {
                Trig::Two(roots) => (roots.angles(self.phi), roots.turns()),
                Trig::Any => {
                    *singular = true;
                    ([0.0; 2], [Turn::ZERO; 2])
                }
                Trig::None(_) => {
                    let delta = delta2.sqrt();
                    let (e, v) = self.lengths;
                    let (near, far) = ((e - v).abs(), e + v);
                    return Err(Miss::metres(
                        "the elbow's annulus",
                        (delta - far).max(near - delta),
                    ));
                }
            };
        Ok([0, 1].map(|m| {
            let moved = self.e + turns[m].rotate(&self.w3, &self.v);
            let (t2, turn2) = angle_and_turn(about(w2, &moved, &d));
            Bend {
                t2,
                t3: angles[m],
                turn2,
                turn3: turns[m],
            }
        }))
    }
}
