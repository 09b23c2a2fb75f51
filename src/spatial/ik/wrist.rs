//! The spherical wrist: joints 4, 5 and 6 revolute, their axes meeting in one point, turning
//! the tool by the rotation the first three joints leave, `R(w4, t4) R(w5, t5) R(w6, t6) = M`.

use core::f64::consts::PI;

use nalgebra::{Matrix3, Vector3};

use super::atan2::atan2;
use super::solver::any_across;
use super::subproblems::{about, angle_and_turn, AxisPair, Turn};

/// How far from square and from parallel (in cosine or sine) the wrist's axes may be for its
/// second solution to be read off the first (see [`Wrist::flips`]): the flip then misplaces
/// the tool by about this much, far below the solutions' rounding.
const FLIP_TOLERANCE: f64 = 1e-14;

/// A wrist's axes at `q = 0` and what the solutions need of them.
pub(crate) struct Wrist {
    w4: Vector3<f64>,
    w5: Vector3<f64>,
    w6: Vector3<f64>,
    pair: AxisPair,
    /// `w5 . w6`, which rotations about axis 5 keep.
    b: f64,
    /// A unit vector across axis 6, and `w6` crossed with it: axis 6's angle is read from it.
    pub across: Vector3<f64>,
    across_turned: Vector3<f64>,
    /// `w6` across axis 5, and `w5 x w6`: the `(cos, sin)` of axis 5's angle taking `w6` to `z`
    /// are their dot products with `z`.
    six_across: Vector3<f64>,
    five_x_six: Vector3<f64>,
    flips: bool,
}

impl Wrist {
    pub fn new(axes: &[Vector3<f64>; 6]) -> Self {
        let (w4, w5, w6) = (axes[3], axes[4], axes[5]);
        let across = any_across(&w6);
        // (t4 + pi, -t5, t6 + pi) is a second solution when R(w4, pi) R(w5, -t5) R(w6, pi)
        // = R(w5, t5): with w4 across w5 the first two are R(w5, t5) R(w4, pi), and
        // R(w4, pi) R(w6, pi) = I needs w6 = +-w4 (the PUMA's, the KUKA's and the Stanford
        // arm's wrists at q = 0).
        let flips = w4.dot(&w5).abs() <= FLIP_TOLERANCE && w4.cross(&w6).norm() <= FLIP_TOLERANCE;
        Self {
            w4,
            w5,
            w6,
            pair: AxisPair::new(&w4, &w5),
            b: w5.dot(&w6),
            across,
            across_turned: w6.cross(&across),
            six_across: w6 - w5 * w5.dot(&w6),
            five_x_six: w5.cross(&w6),
            flips,
        }
    }

    /// `rest w6` and `rest across`, where `rest` is the rotation the whole arm must make; what
    /// the first three joints leave of it, `M`, is then these two with their rotations undone.
    pub fn targets(&self, rest: &Matrix3<f64>) -> (Vector3<f64>, Vector3<f64>) {
        (rest * self.w6, rest * self.across)
    }

    /// Both solutions `(t4, t5, t6)` for the rotation `M` given by `M w6` and `M across`;
    /// `None` if `M w6` cannot be reached (only by rounding: `M` is a rotation).
    pub fn solve(
        &self,
        m_w6: &Vector3<f64>,
        m_across: &Vector3<f64>,
        singular: &mut bool,
    ) -> Option<[[f64; 3]; 2]> {
        let zs = self.pair.meet(self.b, m_w6, 1e-12).ok()?;
        let (first, along) = self.through_z(&zs[0], m_w6, m_across);
        *singular |= along;
        // At the singularity both solutions keep t4 = 0 (the family's representative); the
        // flip would make it pi.
        let second = if self.flips && !along {
            [first[0] + PI, -first[1], first[2] + PI]
        } else {
            let (second, along) = self.through_z(&zs[1], m_w6, m_across);
            *singular |= along;
            second
        };
        Some([first, second])
    }

    /// The solution through `z = R(w5, t5) w6 = R(w4, -t4) M w6`, and whether it is singular
    /// (`z` along axis 4, `t4` free).
    fn through_z(
        &self,
        z: &Vector3<f64>,
        m_w6: &Vector3<f64>,
        m_across: &Vector3<f64>,
    ) -> ([f64; 3], bool) {
        let (w4, w5) = (&self.w4, &self.w5);
        // On the singularity z lies along w4 and t4 is free: t4 = 0 represents it.
        let along = (z - w4 * w4.dot(z)).norm_squared() < 1e-18;
        let (t4, turn4) = if along {
            (0.0, Turn::ZERO)
        } else {
            angle_and_turn(about(w4, z, m_w6))
        };
        let (t5, turn5) = angle_and_turn((self.six_across.dot(z), self.five_x_six.dot(z)));
        // Axis 6's angle from what axes 4 and 5 leave: whatever rounding t4 took near the
        // singularity, t6 makes up for it.
        let seen = turn5
            .inverse()
            .rotate(w5, &turn4.inverse().rotate(w4, m_across));
        let t6 = atan2(self.across_turned.dot(&seen), self.across.dot(&seen));
        ([t4, t5, t6], along)
    }
}
