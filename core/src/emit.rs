//! Emission: straight-line Rust for a derived arm.
//!
//! Each generated method is one [`Program`]: inputs are unpacked into named locals, the joint
//! angles that are needed go together to one call of `planar_arm::trig::sin_cos` (a sine and
//! cosine for each, two angles per SIMD register), trig atoms of angle sums are `let`s
//! named like the paper (`c23`), shared subexpressions are `let`s, and everything used once is
//! inlined. Rational constants are written `10.0 / 3.0` so a reader recognises them (the
//! compiler folds the division). All local identifiers carry `Span::mixed_site()`, so they can
//! neither capture nor be captured by the user's items. Output is deterministic.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use num_traits::{Signed, ToPrimitive, Zero};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use crate::expr::Expr;
use crate::mechanics::{ArmSpec, Dynamics, Kinematics};
use crate::ring::{show, to_f64, to_i128_pair, Rational};
use crate::slp::{Id, Input, Node, OpCount, Program};
use crate::trig::Angle;

/// Why an arm cannot be emitted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EmitError {
    /// What went wrong, lowercase, naming the fix.
    pub message: String,
}

impl std::fmt::Display for EmitError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for EmitError {}

/// Everything derived for one arm, ready to emit.
#[derive(Clone, Debug)]
pub struct Derived {
    /// The arm.
    pub arm: ArmSpec,
    /// Its equations of motion.
    pub dynamics: Dynamics,
    /// Its kinematics.
    pub kinematics: Kinematics,
}

impl Derived {
    /// Derives dynamics and kinematics of the arm.
    #[must_use]
    pub fn new(arm: &ArmSpec) -> Self {
        Self {
            dynamics: Dynamics::derive(arm),
            kinematics: Kinematics::derive(arm),
            arm: arm.clone(),
        }
    }

    fn n(&self) -> usize {
        self.arm.links.len()
    }
}

/// One generated method body: its program, the outputs, and how to name them.
#[derive(Clone, Debug)]
pub struct Method {
    /// The program.
    pub program: Program,
    /// The output nodes with the names of their `let`s.
    pub outputs: Vec<(String, Id)>,
    /// How the program evaluates the method, for its doc comment (empty when it evaluates the
    /// documented formulas term by term).
    pub evaluation: String,
}

impl Method {
    /// The outputs evaluated by the program interpreter (see [`Program::eval`]).
    #[must_use]
    pub fn eval(&self, input: &dyn Fn(Input) -> f64) -> Vec<f64> {
        let values = self.program.eval(input);
        self.outputs
            .iter()
            .map(|(_, id)| values[id.0 as usize])
            .collect()
    }

    /// The operation count of this method.
    #[must_use]
    pub fn op_count(&self) -> OpCount {
        let outs: Vec<Id> = self.outputs.iter().map(|o| o.1).collect();
        self.program.op_count(&outs)
    }

    /// The longest chain of dependent operations to an output (see [`Program::depth`]).
    #[must_use]
    pub fn depth(&self) -> usize {
        let outs: Vec<Id> = self.outputs.iter().map(|o| o.1).collect();
        self.program.depth(&outs)
    }

    fn new(program: Program, outputs: Vec<(String, Id)>) -> Self {
        Self {
            program,
            outputs,
            evaluation: String::new(),
        }
    }

    fn described(mut self, evaluation: &str) -> Self {
        self.evaluation = evaluation.to_string();
        self
    }
}

/// The estimated run time of a method's program, in units of one multiplication: the
/// operations (a division costs about four multiplications, a `sin_cos` call about twenty) plus
/// the longest chain of dependent operations (latency the out-of-order core cannot hide).
/// The chain is weighted one: weighted two, the expanded three-link torques beat the
/// Newton-Euler recursion on paper but measured slower (docs/performance.md).
fn cost(m: &Method) -> usize {
    let count = m.op_count();
    count.mul + count.add + 4 * count.div + 20 * count.sin_cos + m.depth()
}

/// The cheapest candidate by [`cost`]; the first one on a tie (candidates are listed with the
/// term-by-term form first, so that form is kept when nothing beats it).
fn cheapest(candidates: Vec<Method>) -> Method {
    let mut best: Option<(usize, Method)> = None;
    for m in candidates {
        let c = cost(&m);
        if best.as_ref().is_none_or(|(b, _)| c < *b) {
            best = Some((c, m));
        }
    }
    best.expect("at least one candidate").1
}

fn two(i: usize, j: usize) -> String {
    format!("{}{}", i + 1, j + 1)
}

/// The straight-line program of each generated method.
impl Derived {
    /// `M(q)`: the cheaper (by [`OpCount`]) of the expanded entries and an unrolled
    /// composite-rigid-body recursion. Upper triangle; the lower one is the same nodes.
    #[must_use]
    pub fn mass_matrix_method(&self) -> Method {
        cheapest(vec![
            self.mass_matrix_expanded_method(),
            self.mass_matrix_composite_method(),
        ])
    }

    /// `M(q)` evaluated entry by entry from the expanded formulas.
    #[must_use]
    pub fn mass_matrix_expanded_method(&self) -> Method {
        let mut p = Program::new();
        let m = expanded_mass_matrix(&mut p, &self.dynamics);
        Method::new(p, matrix_outputs(&m))
    }

    /// `M(q)` by the composite-rigid-body recursion, unrolled for this arm.
    #[must_use]
    pub fn mass_matrix_composite_method(&self) -> Method {
        let mut p = Program::new();
        let m = composite_mass_matrix(&mut p, &self.arm);
        Method::new(p, matrix_outputs(&m)).described(CRBA)
    }

    /// `c(q, qd)`: the cheaper of the expanded formulas and an unrolled Newton-Euler recursion
    /// (no gravity, no accelerations).
    #[must_use]
    pub fn coriolis_method(&self) -> Method {
        cheapest(vec![
            self.vector_method("cor", &self.dynamics.coriolis),
            self.newton_euler_method("cor", Terms::CORIOLIS),
        ])
    }

    /// `g(q)`: the cheaper of the expanded formulas and an unrolled static recursion.
    #[must_use]
    pub fn gravity_method(&self) -> Method {
        cheapest(vec![
            self.vector_method("g", &self.dynamics.gravity),
            self.newton_euler_method("g", Terms::GRAVITY),
        ])
    }

    /// `tau = M qdd + c + g`: the cheaper of the expanded Lagrangian torques and an unrolled
    /// Newton-Euler recursion.
    #[must_use]
    pub fn inverse_dynamics_method(&self) -> Method {
        cheapest(vec![
            self.inverse_dynamics_lagrange_method(),
            self.inverse_dynamics_newton_euler_method(),
        ])
    }

    /// `tau` from the expanded Lagrangian torques, term by term.
    #[must_use]
    pub fn inverse_dynamics_lagrange_method(&self) -> Method {
        self.vector_method("tau", &self.dynamics.torques)
    }

    /// `tau` by the planar recursive Newton-Euler algorithm unrolled for this arm.
    #[must_use]
    pub fn inverse_dynamics_newton_euler_method(&self) -> Method {
        self.newton_euler_method("tau", Terms::ALL)
    }

    fn newton_euler_method(&self, name: &str, terms: Terms) -> Method {
        let mut p = Program::new();
        let tau = newton_euler(&mut p, &self.arm, terms);
        let outputs = tau
            .into_iter()
            .enumerate()
            .map(|(i, id)| (format!("{name}{}", i + 1), id))
            .collect();
        Method::new(p, outputs).described(RNEA)
    }

    /// `C(q, qd)`.
    #[must_use]
    pub fn coriolis_matrix_method(&self) -> Method {
        let mut p = Program::new();
        let mut outputs = Vec::new();
        for i in 0..self.n() {
            for j in 0..self.n() {
                let id = p.expr(&self.dynamics.coriolis_matrix[i][j]);
                outputs.push((format!("cm{}", two(i, j)), id));
            }
        }
        Method::new(p, outputs)
    }

    /// `T(q, qd)`.
    #[must_use]
    pub fn kinetic_energy_method(&self) -> Method {
        self.vector_method(
            "kinetic",
            std::slice::from_ref(&self.dynamics.kinetic_energy),
        )
    }

    /// `V(q)`.
    #[must_use]
    pub fn potential_energy_method(&self) -> Method {
        self.vector_method(
            "potential",
            std::slice::from_ref(&self.dynamics.potential_energy),
        )
    }

    fn vector_method(&self, name: &str, entries: &[Expr]) -> Method {
        let mut p = Program::new();
        let single = matches!(name, "kinetic" | "potential");
        let outputs = entries
            .iter()
            .enumerate()
            .map(|(i, e)| {
                let label = if single {
                    name.to_string()
                } else {
                    format!("{name}{}", i + 1)
                };
                (label, p.expr(e))
            })
            .collect();
        Method::new(p, outputs)
    }

    /// `qdd = M^-1 (tau - c - g)`: Cramer's rule for one and two joints, an unrolled
    /// `L D L^T` factorisation (no square roots, one division per joint) beyond. `M`, `c` and
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

    /// `det M` of a two-link arm as `det0 + f^2 sin^2 q2`: with `M11 = a + b cos q2`,
    /// `M12 = e + f cos q2`, `M22 = d` and `b d = 2 e f` (always so for a planar arm),
    /// `M11 M22 - M12^2 = (a d - e^2 - f^2) + f^2 sin^2 q2`, where `det0 = det M(q2 = 0) > 0`.
    /// Both terms are non-negative, so unlike `M11 M22 - M12^2` it never cancels to zero or
    /// below. `None` if `M` does not have that form.
    fn two_link_det(&self, p: &mut Program) -> Option<Id> {
        use crate::trig::Trig;
        let q2 = Angle::new(vec![0, 1]);
        let split = |e: &Expr| -> Option<(Rational, Rational)> {
            let (mut k, mut c) = (Rational::zero(), Rational::zero());
            for (mono, t, coeff) in e.terms() {
                if mono.degree() != 0 {
                    return None;
                }
                match t {
                    Trig::One => k += coeff,
                    Trig::Cos(a) if *a == q2 => c += coeff,
                    _ => return None,
                }
            }
            Some((k, c))
        };
        let mm = &self.dynamics.mass_matrix;
        let (a, b) = split(&mm[0][0])?;
        let (e, f) = split(&mm[0][1])?;
        let (d, d_cos) = split(&mm[1][1])?;
        let two = Rational::from_integer(2.into());
        if !d_cos.is_zero() || &b * &d != two * &e * &f {
            return None;
        }
        let det0 = &a * &d - &e * &e - &f * &f;
        if !det0.is_positive() {
            return None;
        }
        let det0 = p.constant(det0);
        let f2 = p.constant(&f * &f);
        let (_, s2) = p.trig_pair(&q2);
        let s2s2 = p.mul(s2, s2);
        let varying = p.mul(f2, s2s2);
        Some(p.add(det0, varying))
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
        let rhs: Vec<Id> = (0..n)
            .map(|i| {
                let tau = p.input(Input::Tau(i));
                let r = p.sub(tau, c[i]);
                p.sub(r, g[i])
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
                let floors: Vec<Rational> = (0..n)
                    .map(|i| pivot_floor(&self.dynamics.mass_matrix[i][i]))
                    .collect();
                ldlt_solve(&mut p, &m, &rhs, &floors)
            }
        };
        let outputs = qdd
            .into_iter()
            .enumerate()
            .map(|(i, id)| (format!("qdd{}", i + 1), id))
            .collect();
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

    /// Tip `x, y`, then `cos` and `sin` of the last link's angle.
    #[must_use]
    pub fn tip_pose_method(&self) -> Method {
        let mut p = Program::new();
        let (x, y) = &self.kinematics.points[self.n()];
        let x = p.expr(x);
        let y = p.expr(y);
        let (c, s) = p.trig_pair(&self.kinematics.tip_angle);
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

/// The doc-comment note of a method evaluated by the unrolled Newton-Euler recursion.
const RNEA: &str = "Evaluated not term by term but by the planar recursive Newton-Euler \
                    algorithm unrolled for this arm (the same function, fewer operations): \
                    link-frame velocities and accelerations outwards, forces and moments \
                    inwards, one rotation by each joint's (cos, sin) per pass, the link \
                    constants folded in.";

/// The doc-comment note of a mass matrix evaluated by the unrolled composite-rigid-body
/// algorithm.
const CRBA: &str = "Evaluated not term by term but by the composite-rigid-body algorithm \
                    unrolled for this arm (the same function, fewer operations): the mass, \
                    first moment and rotational inertia of each tail of the chain, in link \
                    frames, the link constants folded in.";

/// Which terms of `tau = M qdd + c + g` an unrolled Newton-Euler recursion evaluates.
#[derive(Clone, Copy, Debug)]
struct Terms {
    rates: bool,
    accelerations: bool,
    gravity: bool,
}

impl Terms {
    const ALL: Self = Self {
        rates: true,
        accelerations: true,
        gravity: true,
    };
    const CORIOLIS: Self = Self {
        rates: true,
        accelerations: false,
        gravity: false,
    };
    const GRAVITY: Self = Self {
        rates: false,
        accelerations: false,
        gravity: true,
    };
}

/// A planar vector of program nodes.
type V2 = (Id, Id);

/// `(cos q_j, sin q_j)`: joint `j`'s own `sin_cos`.
fn joint_trig(p: &mut Program, j: usize) -> V2 {
    p.trig_pair(&Angle::range(j, j + 1))
}

/// `R(q) v`: a vector of link `j`'s frame in link `j - 1`'s frame (`cs = (cos q_j, sin q_j)`).
fn rotate(p: &mut Program, cs: V2, v: V2) -> V2 {
    let (c, s) = cs;
    let (a, b) = (p.mul(c, v.0), p.mul(s, v.1));
    let x = p.sub(a, b);
    let (a, b) = (p.mul(s, v.0), p.mul(c, v.1));
    (x, p.add(a, b))
}

/// `R(-q) v`: a vector of link `j - 1`'s frame in link `j`'s frame.
fn rotate_back(p: &mut Program, cs: V2, v: V2) -> V2 {
    let (c, s) = cs;
    let (a, b) = (p.mul(c, v.0), p.mul(s, v.1));
    let x = p.add(a, b);
    let (a, b) = (p.mul(c, v.1), p.mul(s, v.0));
    (x, p.sub(a, b))
}

/// Joint torques by the planar recursive Newton-Euler algorithm, unrolled for the arm, in link
/// frames (x along the link): each link's angular velocity `w` and acceleration `al`, and the
/// acceleration `a` of its joint, outwards (gravity as an upward acceleration of the base);
/// the force each link's tail exerts on it and the moment about its joint, inwards.
fn newton_euler(p: &mut Program, arm: &ArmSpec, terms: Terms) -> Vec<Id> {
    let n = arm.links.len();
    let zero = p.constant(Rational::zero());
    let k = |p: &mut Program, r: Rational| p.constant(r);
    let g = k(
        p,
        if terms.gravity {
            arm.gravity.clone()
        } else {
            Rational::zero()
        },
    );
    // Acceleration of the current joint in the previous link's frame.
    let mut end: V2 = (zero, g);
    let (mut w, mut al) = (zero, zero);
    let mut trig = Vec::with_capacity(n);
    let mut force = Vec::with_capacity(n);
    let mut alpha = Vec::with_capacity(n);
    let mut accel = Vec::with_capacity(n);
    for (i, link) in arm.links.iter().enumerate() {
        let cs = joint_trig(p, i);
        let a = rotate_back(p, cs, end);
        p.set_name(a.0, format!("ax{}", i + 1));
        p.set_name(a.1, format!("ay{}", i + 1));
        if terms.rates {
            let qd = p.input(Input::Qd(i));
            w = p.add(w, qd);
            p.set_name(w, format!("w{}", i + 1));
        }
        if terms.accelerations {
            let qdd = p.input(Input::Qdd(i));
            al = p.add(al, qdd);
            p.set_name(al, format!("al{}", i + 1));
        }
        let w2 = p.mul(w, w);
        // The force on the link's centre of mass, m (a + com (-w^2, al)).
        let m = k(p, link.mass.clone());
        let mc = k(p, &link.mass * &link.com);
        let fx = {
            let (u, v) = (p.mul(m, a.0), p.mul(mc, w2));
            p.sub(u, v)
        };
        let fy = {
            let (u, v) = (p.mul(m, a.1), p.mul(mc, al));
            p.add(u, v)
        };
        // The far end of the link: a + l (-w^2, al).
        let l = k(p, link.length.clone());
        end = {
            let (u, v) = (p.mul(l, w2), p.mul(l, al));
            (p.sub(a.0, u), p.add(a.1, v))
        };
        p.set_name(end.0, format!("ex{}", i + 1));
        p.set_name(end.1, format!("ey{}", i + 1));
        trig.push(cs);
        force.push((fx, fy));
        alpha.push(al);
        accel.push(a.1);
    }
    let mut tau = vec![zero; n];
    let mut tail: Option<V2> = None;
    let mut moment = zero;
    for i in (0..n).rev() {
        let link = &arm.links[i];
        // Moment about the joint of the link's own inertia forces:
        // (I + m com^2) al + m com ay (the centripetal force passes through the joint).
        let inertia = k(p, &link.inertia + &link.mass * &link.com * &link.com);
        let mc = k(p, &link.mass * &link.com);
        let (u, v) = (p.mul(inertia, alpha[i]), p.mul(mc, accel[i]));
        let mut here = p.add(u, v);
        let mut f = force[i];
        if let Some(child) = tail {
            // The force the tail exerts at the far end of the link, in this link's frame.
            let r = rotate(p, trig[i + 1], child);
            let l = k(p, link.length.clone());
            let lever = p.mul(l, r.1);
            here = p.add(here, lever);
            f = (p.add(f.0, r.0), p.add(f.1, r.1));
        }
        p.set_name(f.0, format!("fx{}", i + 1));
        p.set_name(f.1, format!("fy{}", i + 1));
        moment = p.add(moment, here);
        tau[i] = moment;
        tail = Some(f);
    }
    tau
}

/// The mass matrix by the composite-rigid-body algorithm, unrolled for the arm, in link frames:
/// for each tail of the chain (links `j..`), its mass, first moment `h` about joint `j` and
/// rotational inertia about joint `j` (`M_jj`); `M_ij = M_(i+1)j + l_i (h in link i's frame).x`.
fn composite_mass_matrix(p: &mut Program, arm: &ArmSpec) -> Vec<Vec<Id>> {
    let n = arm.links.len();
    let zero = p.constant(Rational::zero());
    let trig: Vec<V2> = (0..n).map(|j| joint_trig(p, j)).collect();
    let mut m = vec![vec![zero; n]; n];
    let mut tail_mass = Rational::zero();
    let mut tail: Option<(V2, Id)> = None;
    for j in (0..n).rev() {
        let link = &arm.links[j];
        let own = &link.mass * &link.com;
        let hx = p.constant(&own + &tail_mass * &link.length);
        let rot =
            p.constant(&link.inertia + &own * &link.com + &tail_mass * &link.length * &link.length);
        let (h, rot) = match tail {
            None => ((hx, zero), rot),
            Some((child, child_rot)) => {
                let r = rotate(p, trig[j + 1], child);
                let two_l = p.constant(&link.length * Rational::from_integer(2.into()));
                let shift = p.mul(two_l, r.0);
                let rot = p.add(rot, child_rot);
                ((p.add(hx, r.0), r.1), p.add(rot, shift))
            }
        };
        p.set_name(h.0, format!("hx{}", j + 1));
        p.set_name(h.1, format!("hy{}", j + 1));
        tail_mass += &link.mass;
        m[j][j] = rot;
        let (mut v, mut mij) = (h, rot);
        for i in (0..j).rev() {
            v = rotate(p, trig[i + 1], v);
            let l = p.constant(arm.links[i].length.clone());
            let step = p.mul(l, v.0);
            mij = p.add(mij, step);
            m[i][j] = mij;
            m[j][i] = mij;
        }
        tail = Some((h, rot));
    }
    m
}

/// The mass matrix from the expanded entries (upper triangle; the lower is the same nodes).
fn expanded_mass_matrix(p: &mut Program, d: &Dynamics) -> Vec<Vec<Id>> {
    let n = d.n;
    (0..n)
        .map(|i| {
            (0..n)
                .map(|j| p.expr(&d.mass_matrix[i.min(j)][i.max(j)]))
                .collect()
        })
        .collect()
}

/// Row-major outputs `m11, m12, ...` of a symmetric matrix (repeated nodes below the diagonal).
fn matrix_outputs(m: &[Vec<Id>]) -> Vec<(String, Id)> {
    let mut outputs = Vec::new();
    for (i, row) in m.iter().enumerate() {
        for (j, &id) in row.iter().enumerate() {
            outputs.push((format!("m{}", two(i.min(j), i.max(j))), id));
        }
    }
    outputs
}

/// Solves `M x = b` with `M = L D L^T` unrolled (Crout's order, one multiplication per
/// inner-product term): `s_ij = M_ij - sum_k L_ik s_jk` is `L_ij d_j`, so `L_ij = s_ij / d_j`
/// and `d_i = M_ii - sum_k L_ik s_ik`; then `L y = b`, `z = y / d`, `L^T x = z`.
/// The floor under pivot `d_i` of `L D L^T`: 2^-52 times a bound on `|M_ii|` over all
/// configurations (the sum of its coefficients' magnitudes), the level of the rounding noise in
/// the computed pivot. `M` is positive definite, so its exact pivots are positive; a computed
/// one at or below the floor only means `M` is too ill-conditioned for `f64` there, and the
/// floor keeps the accelerations finite instead of infinite or NaN.
fn pivot_floor(m_ii: &Expr) -> Rational {
    let bound = m_ii
        .terms()
        .fold(Rational::zero(), |acc, (_, _, c)| acc + c.abs());
    bound / Rational::from_integer(num_bigint::BigInt::from(1u64 << 52))
}

fn ldlt_solve(p: &mut Program, m: &[Vec<Id>], b: &[Id], floors: &[Rational]) -> Vec<Id> {
    let n = m.len();
    let zero = p.constant(Rational::zero());
    let one = p.constant(Rational::from_integer(1.into()));
    // s[i][j] = L_ij d_j and l[i][j] = L_ij for j < i.
    let mut s = vec![vec![zero; n]; n];
    let mut l = vec![vec![zero; n]; n];
    let mut inv_d = vec![zero; n];
    for i in 0..n {
        for j in 0..i {
            let mut sij = m[i][j];
            for k in 0..j {
                let w = p.mul(l[i][k], s[j][k]);
                sij = p.sub(sij, w);
            }
            s[i][j] = sij;
            let lij = p.mul(sij, inv_d[j]);
            p.set_name(lij, format!("l{}", two(i, j)));
            l[i][j] = lij;
        }
        let mut di = m[i][i];
        for k in 0..i {
            let w = p.mul(l[i][k], s[i][k]);
            di = p.sub(di, w);
        }
        let floor = p.constant(floors[i].clone());
        let di = p.max(di, floor);
        p.set_name(di, format!("d{}", i + 1));
        let inv = p.div(one, di);
        p.set_name(inv, format!("inv_d{}", i + 1));
        inv_d[i] = inv;
    }
    // L y = b
    let mut y = Vec::with_capacity(n);
    for i in 0..n {
        let mut yi = b[i];
        for (k, &yk) in y.iter().enumerate() {
            let w = p.mul(l[i][k], yk);
            yi = p.sub(yi, w);
        }
        y.push(yi);
    }
    // D z = y, L^T x = z
    let mut x = vec![zero; n];
    for i in (0..n).rev() {
        let mut xi = p.mul(y[i], inv_d[i]);
        for k in i + 1..n {
            let w = p.mul(l[k][i], x[k]);
            xi = p.sub(xi, w);
        }
        x[i] = xi;
    }
    x
}

/// `f64` tokens of an exact constant: `2.0`, `(10.0 / 3.0)`, or the nearest `f64` when the
/// numerator or denominator is not exact in `f64`.
///
/// # Errors
/// If the value is outside the finite `f64` range.
pub fn f64_tokens(r: &Rational) -> Result<TokenStream, EmitError> {
    const EXACT: u64 = 1 << 53;
    let value = to_f64(r).ok_or_else(|| EmitError {
        message: format!("the constant {} does not fit in f64", show(r)),
    })?;
    let magnitude = r.abs();
    let num = magnitude.numer().to_u64().filter(|&v| v <= EXACT);
    let den = magnitude.denom().to_u64().filter(|&v| v <= EXACT);
    let body = match (num, den) {
        #[allow(clippy::cast_precision_loss)] // both are at most 2^53, exact in f64
        (Some(a), Some(1)) => {
            let a = Literal::f64_unsuffixed(a as f64);
            quote!(#a)
        }
        #[allow(clippy::cast_precision_loss)]
        (Some(a), Some(b)) => {
            let (a, b) = (
                Literal::f64_unsuffixed(a as f64),
                Literal::f64_unsuffixed(b as f64),
            );
            quote!((#a / #b))
        }
        _ => {
            let v = Literal::f64_unsuffixed(value.abs());
            quote!(#v)
        }
    };
    Ok(if r.is_negative() {
        quote!((-#body))
    } else {
        body
    })
}

/// Precedence of an emitted expression, to place parentheses.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Sum,
    Product,
    Atom,
}

/// Renders a method's program as `let` statements and the output identifiers.
pub struct Rendered {
    /// The statements, in order.
    pub statements: Vec<TokenStream>,
    /// One identifier per output, in order.
    pub outputs: Vec<Ident>,
    /// Which inputs are read.
    pub inputs_used: std::collections::BTreeSet<Input>,
}

/// A local identifier that neither captures nor is captured by the user's names.
#[must_use]
pub fn local(name: &str) -> Ident {
    if name == "_" {
        return Ident::new(name, Span::mixed_site());
    }
    Ident::new(&format!("__{name}"), Span::mixed_site())
}

/// The local name of an input.
#[must_use]
pub fn input_name(i: Input) -> String {
    match i {
        Input::Q(j) => format!("q{}", j + 1),
        Input::Qd(j) => format!("qd{}", j + 1),
        Input::Qdd(j) => format!("qdd{}", j + 1),
        Input::Tau(j) => format!("tau{}", j + 1),
        Input::Force(0) => "u".into(),
        Input::Force(_) => "v".into(),
        Input::TipTorque => "torque".into(),
    }
}

/// Renders a method.
///
/// # Errors
/// If a constant does not fit in `f64`.
pub fn render(method: &Method) -> Result<Rendered, EmitError> {
    let p = &method.program;
    let out_ids: Vec<Id> = method.outputs.iter().map(|o| o.1).collect();
    let uses = p.use_counts(&out_ids);
    let mut taken: std::collections::BTreeSet<String> = std::collections::BTreeSet::new();
    let fresh = |base: &str, taken: &mut std::collections::BTreeSet<String>| -> String {
        let mut name = base.to_string();
        let mut k = 2;
        while taken.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        taken.insert(name.clone());
        name
    };
    // Reserve input and per-joint trig names first.
    let mut inputs_used = std::collections::BTreeSet::new();
    let mut joints: BTreeMap<usize, (bool, bool)> = BTreeMap::new();
    for (node, &u) in p.nodes().iter().zip(&uses) {
        if u == 0 {
            continue;
        }
        match *node {
            Node::Input(i) => {
                inputs_used.insert(i);
            }
            Node::Sin(j) => joints.entry(j).or_default().0 = true,
            Node::Cos(j) => joints.entry(j).or_default().1 = true,
            _ => {}
        }
    }
    for &j in joints.keys() {
        inputs_used.insert(Input::Q(j));
    }
    for &i in &inputs_used {
        taken.insert(input_name(i));
    }
    for &j in joints.keys() {
        taken.insert(format!("s{}", j + 1));
        taken.insert(format!("c{}", j + 1));
    }
    let output_of: BTreeMap<Id, &str> = method
        .outputs
        .iter()
        .rev()
        .map(|(name, id)| (*id, name.as_str()))
        .collect();

    let mut statements = Vec::new();
    if !joints.is_empty() {
        // One call for all the angles: the kernel evaluates them two at a time in SIMD lanes.
        let mut angles = Vec::new();
        let mut pairs = Vec::new();
        for (&j, &(s, c)) in &joints {
            angles.push(local(&input_name(Input::Q(j))));
            let name = |used: bool, prefix: &str| {
                if used {
                    local(&format!("{prefix}{}", j + 1))
                } else {
                    local("_")
                }
            };
            let (s, c) = (name(s, "s"), name(c, "c"));
            pairs.push(quote!((#s, #c)));
        }
        statements.push(quote!(
            let [#(#pairs),*] = ::planar_arm::__private::sin_cos([#(#angles),*]);
        ));
    }
    let mut exprs: Vec<Option<(Prec, TokenStream)>> = vec![None; p.nodes().len()];
    let mut temp = 0usize;
    for (idx, node) in p.nodes().iter().enumerate() {
        if uses[idx] == 0 {
            continue;
        }
        let id = Id(u32::try_from(idx).unwrap_or(u32::MAX));
        let get = |c: Id, exprs: &Vec<Option<(Prec, TokenStream)>>| {
            exprs[c.0 as usize]
                .clone()
                .unwrap_or((Prec::Atom, quote!(0.0)))
        };
        let paren = |(prec, ts): (Prec, TokenStream), min: Prec| {
            if prec >= min {
                ts
            } else {
                quote!((#ts))
            }
        };
        let (prec, ts) = match node {
            Node::Input(i) => (Prec::Atom, local(&input_name(*i)).into_token_stream()),
            Node::Const(r) => (Prec::Atom, f64_tokens(r)?),
            Node::Sin(j) => (
                Prec::Atom,
                local(&format!("s{}", j + 1)).into_token_stream(),
            ),
            Node::Cos(j) => (
                Prec::Atom,
                local(&format!("c{}", j + 1)).into_token_stream(),
            ),
            Node::Add(a, b) => {
                let (a, b) = (
                    paren(get(*a, &exprs), Prec::Sum),
                    paren(get(*b, &exprs), Prec::Sum),
                );
                (Prec::Sum, quote!(#a + #b))
            }
            Node::Sub(a, b) => {
                let a = paren(get(*a, &exprs), Prec::Sum);
                let b = paren(get(*b, &exprs), Prec::Product);
                (Prec::Sum, quote!(#a - #b))
            }
            Node::Mul(a, b) => {
                let (a, b) = (
                    paren(get(*a, &exprs), Prec::Product),
                    paren(get(*b, &exprs), Prec::Product),
                );
                (Prec::Product, quote!(#a * #b))
            }
            Node::Div(a, b) => {
                let a = paren(get(*a, &exprs), Prec::Product);
                let b = paren(get(*b, &exprs), Prec::Atom);
                (Prec::Product, quote!(#a / #b))
            }
            Node::Max(a, b) => {
                let a = paren(get(*a, &exprs), Prec::Atom);
                let (_, b) = get(*b, &exprs);
                (Prec::Atom, quote!(#a.max(#b)))
            }
            Node::Neg(a) => {
                let a = paren(get(*a, &exprs), Prec::Atom);
                (Prec::Sum, quote!(-#a))
            }
        };
        let is_leaf = matches!(
            node,
            Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_)
        );
        let named = p.name(id).is_some() && !is_leaf;
        let is_output = output_of.contains_key(&id);
        if !is_leaf && (uses[idx] > 1 || named || is_output) {
            let base = output_of
                .get(&id)
                .map(|s| (*s).to_string())
                .or_else(|| p.name(id).map(str::to_string))
                .unwrap_or_else(|| {
                    temp += 1;
                    format!("t{temp}")
                });
            let name = local(&fresh(&base, &mut taken));
            statements.push(quote!(let #name = #ts;));
            exprs[idx] = Some((Prec::Atom, name.into_token_stream()));
        } else {
            exprs[idx] = Some((prec, ts));
        }
    }
    let mut outputs = Vec::new();
    for (name, id) in &method.outputs {
        let (_, ts) = exprs[id.0 as usize]
            .clone()
            .unwrap_or((Prec::Atom, quote!(0.0)));
        // Leaves and repeated outputs (the symmetric half of M) get their own readable let.
        let ident = match syn_ident(&ts) {
            Some(existing) => existing,
            None => {
                let ident = local(&fresh(name, &mut taken));
                statements.push(quote!(let #ident = #ts;));
                exprs[id.0 as usize] = Some((Prec::Atom, ident.clone().into_token_stream()));
                ident
            }
        };
        outputs.push(ident);
    }
    Ok(Rendered {
        statements,
        outputs,
        inputs_used,
    })
}

use quote::ToTokens as _;

/// The identifier, if the tokens are a single identifier.
fn syn_ident(ts: &TokenStream) -> Option<Ident> {
    let mut it = ts.clone().into_iter();
    match (it.next(), it.next()) {
        (Some(proc_macro2::TokenTree::Ident(i)), None) => Some(i),
        _ => None,
    }
}

/// Human-readable formulas for a method's doc comment.
#[must_use]
pub fn formula_doc(title: &str, rows: &[(String, &Expr)]) -> String {
    let mut s = format!("{title}\n\n```text\n");
    for (name, e) in rows {
        let _ = writeln!(s, "{name} = {e}");
    }
    s.push_str("```\n");
    s
}

/// Fails if a derived coefficient cannot be emitted as `const` data (`i128`) or as `f64`.
///
/// # Errors
/// Names the first entry whose coefficient does not fit.
pub fn check_representable(d: &Derived) -> Result<(), EmitError> {
    let check = |what: &str, e: &Expr| -> Result<(), EmitError> {
        for (_, _, c) in e.terms() {
            if to_i128_pair(c).is_none() || to_f64(c).is_none() || c.is_zero() {
                return Err(EmitError {
                    message: format!(
                        "the exact coefficient {} in {what} does not fit in i128 and f64; \
                         choose link parameters with smaller numerators and denominators",
                        show(c)
                    ),
                });
            }
        }
        Ok(())
    };
    check("the kinetic energy", &d.dynamics.kinetic_energy)?;
    check("the potential energy", &d.dynamics.potential_energy)?;
    for (i, row) in d.dynamics.mass_matrix.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            check(&format!("M{}", two(i, j)), e)?;
        }
    }
    for (i, e) in d.dynamics.coriolis.iter().enumerate() {
        check(&format!("c{}", i + 1), e)?;
    }
    for (i, e) in d.dynamics.gravity.iter().enumerate() {
        check(&format!("g{}", i + 1), e)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mechanics::LinkSpec;
    use crate::ring::ratio;

    /// An arm with uneven parameters (an offset centre of mass, a counterweight).
    fn arm(n: usize) -> ArmSpec {
        let k = |i: usize| i64::try_from(i).unwrap_or(0);
        ArmSpec {
            links: (0..n)
                .map(|i| LinkSpec {
                    length: ratio(k(i) + 3, 4),
                    mass: ratio(2 * k(i) + 1, 3),
                    inertia: ratio(1, k(i) + 5),
                    com: ratio(k(i % 3) - 1, 2),
                })
                .collect(),
            gravity: ratio(981, 100),
        }
    }

    fn eval(m: &Method, n: usize) -> Vec<f64> {
        #[allow(clippy::cast_precision_loss)]
        let at = |j: usize, k: f64| (j as f64 + 1.0).mul_add(0.37, k).sin() * 2.0;
        m.eval(&|i| match i {
            Input::Q(j) => at(j, 0.1),
            Input::Qd(j) => at(j, 1.3),
            Input::Qdd(j) => at(j, 2.9),
            Input::Tau(j) => at(j + n, 4.1) * 10.0,
            Input::Force(_) | Input::TipTorque => 0.0,
        })
    }

    #[track_caller]
    fn same(a: &[f64], b: &[f64], what: &str) {
        let scale = a.iter().chain(b).fold(1.0_f64, |m, x| m.max(x.abs()));
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= 1e-11 * scale, "{what}: {a:?} vs {b:?}");
        }
    }

    #[test]
    fn every_candidate_agrees() {
        for n in 1..=7 {
            let d = Derived::new(&arm(n));
            let tau = eval(&d.inverse_dynamics_lagrange_method(), n);
            same(
                &tau,
                &eval(&d.inverse_dynamics_newton_euler_method(), n),
                "tau",
            );
            let m = eval(&d.mass_matrix_expanded_method(), n);
            same(&m, &eval(&d.mass_matrix_composite_method(), n), "M");
            same(
                &eval(&d.vector_method("c", &d.dynamics.coriolis), n),
                &eval(&d.newton_euler_method("c", Terms::CORIOLIS), n),
                "c",
            );
            same(
                &eval(&d.vector_method("g", &d.dynamics.gravity), n),
                &eval(&d.newton_euler_method("g", Terms::GRAVITY), n),
                "g",
            );
            let fd = eval(&d.forward_dynamics_with(false, false, false), n);
            for k in 1..8 {
                let with = d.forward_dynamics_with(k & 1 == 1, k & 2 == 2, k & 4 == 4);
                same(&fd, &eval(&with, n), "qdd");
            }
        }
    }

    #[test]
    #[ignore = "prints a table"]
    fn print_op_counts() {
        for n in 1..=8 {
            let d = Derived::new(&arm(n));
            let show =
                |m: Method| format!("{} depth {} cost {}", m.op_count(), m.depth(), cost(&m));
            println!("N = {n}");
            println!(
                "  tau lagrange     {}",
                show(d.inverse_dynamics_lagrange_method())
            );
            println!(
                "  tau newton-euler {}",
                show(d.inverse_dynamics_newton_euler_method())
            );
            println!(
                "  M expanded       {}",
                show(d.mass_matrix_expanded_method())
            );
            println!(
                "  M composite      {}",
                show(d.mass_matrix_composite_method())
            );
            println!(
                "  c expanded       {}",
                show(d.vector_method("c", &d.dynamics.coriolis))
            );
            println!(
                "  c newton-euler   {}",
                show(d.newton_euler_method("c", Terms::CORIOLIS))
            );
            println!(
                "  g expanded       {}",
                show(d.vector_method("g", &d.dynamics.gravity))
            );
            println!(
                "  g recursion      {}",
                show(d.newton_euler_method("g", Terms::GRAVITY))
            );
            for k in 0..8 {
                let (a, b, c) = (k & 1 == 1, k & 2 == 2, k & 4 == 4);
                let fd = d.forward_dynamics_with(a, b, c);
                println!("  fd M-crba={a} c-rnea={b} g-rec={c} {}", show(fd));
            }
        }
    }
}
