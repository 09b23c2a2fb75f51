//! The program of the forward dynamics, `qdd = M^-1 (tau - c - g - f)`: Cramer's rule for one
//! and two joints, an unrolled `L D L^T` solve beyond, on M, c and g as their own methods
//! evaluate them.

use num_traits::{Signed, Zero};

use super::dynamics::expanded_mass_matrix;
use super::{vector_outputs, Derived, Method};
use crate::expr::Expr;
use crate::programs::unrolled::{
    composite_mass_matrix, ldlt_solve, newton_euler, pivot_floor, Terms,
};
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input, Program};
use crate::trig::Angle;

impl<C: Emit> Derived<C> {
    /// `qdd = M^-1 (tau - c - g)`: Cramer's rule for one and two joints, an unrolled
    /// `L D L^T` factorisation (no square roots, one division per joint) beyond. The derive
    /// emits it for one and two joints; from three, `forward_dynamics` is
    /// `mass_matrix_and_bias` followed by the run-time crate's solve (the same factorisation,
    /// see `generate`), and this program is the base of the emitted forward derivatives. `M`, `c` and
    /// `g` are evaluated exactly as [`mass_matrix_method`](Self::mass_matrix_method),
    /// [`coriolis_method`](Self::coriolis_method) and [`gravity_method`](Self::gravity_method)
    /// evaluate them (whichever of the expanded formulas and the unrolled recursions each
    /// chose), so the result solves the very system those methods return: `tau - c - g` is
    /// formed in the same order, bit for bit.
    #[must_use]
    pub fn forward_dynamics_method(&self) -> Method {
        let recursive = |m: Method| !m.evaluation.is_empty();
        self.forward_dynamics_with(
            recursive(self.mass_matrix_method()),
            recursive(self.coriolis_method()),
            recursive(self.gravity_method()),
        )
    }

    /// Forward dynamics with `M` from the composite-rigid-body recursion or the expanded
    /// entries, and `c` and `g` each from the Newton-Euler recursion or the expanded formulas.
    #[must_use]
    pub fn forward_dynamics_with(
        &self,
        composite: bool,
        recursive_c: bool,
        recursive_g: bool,
    ) -> Method {
        let n = self.n();
        let mut p = Program::new();
        let m = if composite {
            composite_mass_matrix(&mut p, &self.arm)
        } else {
            expanded_mass_matrix(&mut p, &self.dynamics)
        };
        let c: Vec<Id> = if recursive_c {
            newton_euler(&mut p, &self.arm, Terms::CORIOLIS)
        } else {
            self.dynamics.coriolis.iter().map(|e| p.expr(e)).collect()
        };
        let g: Vec<Id> = if recursive_g {
            newton_euler(&mut p, &self.arm, Terms::GRAVITY)
        } else {
            self.dynamics.gravity.iter().map(|e| p.expr(e)).collect()
        };
        let f = self.friction_nodes(&mut p);
        let rhs: Vec<Id> = (0..n)
            .map(|i| {
                let tau = p.input(Input::Tau(i));
                let r = p.sub(tau, c[i]);
                let r = p.sub(r, g[i]);
                p.sub(r, f[i])
            })
            .collect();
        for (i, &r) in rhs.iter().enumerate() {
            p.set_name(r, format!("rhs{}", i + 1));
        }
        let qdd = match n {
            1 => vec![p.div(rhs[0], m[0][0])],
            2 => {
                let det = self.two_link_det(&mut p).unwrap_or_else(|| {
                    let a = p.mul(m[0][0], m[1][1]);
                    let b = p.mul(m[0][1], m[0][1]);
                    p.sub(a, b)
                });
                p.set_name(det, "det".into());
                let x0 = {
                    let u = p.mul(m[1][1], rhs[0]);
                    let v = p.mul(m[0][1], rhs[1]);
                    p.sub(u, v)
                };
                let x1 = {
                    let u = p.mul(m[0][0], rhs[1]);
                    let v = p.mul(m[0][1], rhs[0]);
                    p.sub(u, v)
                };
                vec![p.div(x0, det), p.div(x1, det)]
            }
            _ => {
                let floors: Vec<Id> = (0..n)
                    .map(|i| pivot_floor(&mut p, &self.dynamics.mass_matrix[i][i], m[i][i]))
                    .collect();
                ldlt_solve(&mut p, &m, &rhs, &floors)
            }
        };
        let outputs = vector_outputs("qdd", qdd);
        let form = |recursive: bool, how: &str| {
            if recursive {
                format!("by the {how} unrolled for this arm")
            } else {
                "from the formulas".to_string()
            }
        };
        let evaluation = if composite || recursive_c || recursive_g {
            format!(
                "M, c and g evaluated as `mass_matrix`, `coriolis` and `gravity` evaluate them: \
                 M {}, c {}, g {}.",
                form(composite, "composite-rigid-body algorithm"),
                form(recursive_c, "recursive Newton-Euler algorithm"),
                form(recursive_g, "static recursion"),
            )
        } else {
            String::new()
        };
        Method::new(p, outputs).described(&evaluation)
    }

    /// `det M` of a two-link arm as `det0 + f^2 sin^2 q2`: with `M11 = a + b cos q2`,
    /// `M12 = e + f cos q2`, `M22 = d` and `b d = 2 e f` (always so for a planar arm whose
    /// centres of mass lie on the links),
    /// `M11 M22 - M12^2 = (a d - e^2 - f^2) + f^2 sin^2 q2`, where `det0 = det M(q2 = 0) > 0`.
    /// Both terms are non-negative, so unlike `M11 M22 - M12^2` it never cancels to zero or
    /// below. `None` if `M` does not have that form.
    pub(crate) fn two_link_det(&self, p: &mut Program) -> Option<Id> {
        use crate::trig::Trig;
        let q2 = Angle::new(vec![0, 1]);
        let zero = || C::from_rational(Rational::zero());
        let split = |e: &Expr<C>| -> Option<(C, C)> {
            let (mut k, mut c) = (zero(), zero());
            for (mono, t, coeff) in e.terms() {
                if mono.degree() != 0 {
                    return None;
                }
                match t {
                    Trig::One => k = k + coeff.clone(),
                    Trig::Cos(a) if *a == q2 => c = c + coeff.clone(),
                    _ => return None,
                }
            }
            Some((k, c))
        };
        let mm = &self.dynamics.mass_matrix;
        let (a, b) = split(&mm[0][0])?;
        let (e, f) = split(&mm[0][1])?;
        let (d, d_cos) = split(&mm[1][1])?;
        if !d_cos.is_zero()
            || b * d.clone() != (e.clone() * f.clone()).scale(&Rational::from_integer(2.into()))
        {
            return None;
        }
        let exact = a.clone() * d.clone() - e.clone() * e.clone() - f.clone() * f.clone();
        let (det0, f2) = match exact.rational() {
            Some(r) if !r.is_positive() => return None,
            Some(r) => (p.constant(r), p.coefficient(&(f.clone() * f))),
            // With run-time parameters the sign is not known here (det0 is det M at q2 = 0,
            // positive for any physical arm), and det0 is formed from the nodes of a, d, e
            // and f, which M's entries compute anyway, rather than expanded into a
            // polynomial in the parameters.
            None => {
                let (a, d, e, f) = (
                    p.coefficient(&a),
                    p.coefficient(&d),
                    p.coefficient(&e),
                    p.coefficient(&f),
                );
                let (ad, ee, ff) = (p.mul(a, d), p.mul(e, e), p.mul(f, f));
                let ad_ee = p.sub(ad, ee);
                (p.sub(ad_ee, ff), ff)
            }
        };
        let (_, s2) = p.trig_pair(&q2);
        let s2s2 = p.mul(s2, s2);
        let varying = p.mul(f2, s2s2);
        Some(p.add(det0, varying))
    }
}
