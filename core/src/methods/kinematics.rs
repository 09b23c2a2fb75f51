//! The programs of the kinematics and statics: the tip pose, the Jacobian, the joints'
//! positions, the tip in polar form and `J^T` of a tip load.

use super::{Derived, Method};
use crate::programs::method::two;
use crate::programs::unrolled::turn;
use crate::slp::{Emit, Input, Program};

impl<C: Emit> Derived<C> {
    /// Tip `x, y`, then `cos` and `sin` of the last link's angle.
    #[must_use]
    pub fn tip_pose_method(&self) -> Method {
        let mut p = Program::new();
        let (x, y) = &self.kinematics.points[self.n()];
        let x = p.expr(x);
        let y = p.expr(y);
        let angle = p.trig_pair(&self.kinematics.tip_angle);
        let (c, s) = turn(&mut p, angle, &self.kinematics.tip_turn);
        Method::new(
            p,
            vec![
                ("x".into(), x),
                ("y".into(), y),
                ("cos_phi".into(), c),
                ("sin_phi".into(), s),
            ],
        )
    }

    /// The 3 x N Jacobian, row-major.
    #[must_use]
    pub fn jacobian_method(&self) -> Method {
        let mut p = Program::new();
        let mut outputs = Vec::new();
        for (r, row) in self.kinematics.jacobian.iter().enumerate() {
            for (j, e) in row.iter().enumerate() {
                outputs.push((format!("j{}", two(r, j)), p.expr(e)));
            }
        }
        Method::new(p, outputs)
    }

    /// Joints `1..=N`: `x, y` of each.
    #[must_use]
    pub fn joint_positions_method(&self) -> Method {
        let mut p = Program::new();
        let mut outputs = Vec::new();
        for (i, (x, y)) in self.kinematics.points.iter().take(self.n()).enumerate() {
            outputs.push((format!("x{}", i + 1), p.expr(x)));
            outputs.push((format!("y{}", i + 1), p.expr(y)));
        }
        Method::new(p, outputs)
    }

    /// `r^2`, tip `x`, tip `y`.
    #[must_use]
    pub fn tip_polar_method(&self) -> Method {
        let mut p = Program::new();
        let r2 = p.expr(&self.kinematics.radius_squared);
        let (x, y) = &self.kinematics.points[self.n()];
        let x = p.expr(x);
        let y = p.expr(y);
        Method::new(p, vec![("r2".into(), r2), ("x".into(), x), ("y".into(), y)])
    }

    /// `tau = J^T (u, v, torque)`.
    #[must_use]
    pub fn joint_torques_method(&self) -> Method {
        let mut p = Program::new();
        let u = p.input(Input::Force(0));
        let v = p.input(Input::Force(1));
        let t = p.input(Input::TipTorque);
        let mut outputs = Vec::new();
        for j in 0..self.n() {
            let jx = p.expr(&self.kinematics.jacobian[0][j]);
            let jy = p.expr(&self.kinematics.jacobian[1][j]);
            let a = p.mul(jx, u);
            let b = p.mul(jy, v);
            let ab = p.add(a, b);
            outputs.push((format!("tau{}", j + 1), p.add(ab, t)));
        }
        Method::new(p, outputs)
    }
}
