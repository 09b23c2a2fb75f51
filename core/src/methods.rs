//! Which straight-line program computes each generated method.
//!
//! For every method the derive emits there may be several programs that compute the same
//! function: the expanded exact formulas term by term, or a recursion (Newton-Euler,
//! composite-rigid-body) unrolled for the arm with its constants folded in. [`Derived`] builds
//! the candidates and keeps the cheapest by an estimate of run time ([`Method`], `cost`);
//! [`emit`](crate::emit) then writes the chosen program as Rust.

use num_traits::{Signed, Zero};

use crate::expr::Expr;
use crate::mechanics::{ArmSpec, Dynamics, Kinematics};
use crate::programs::unrolled::{
    composite_mass_matrix, ldlt_solve, newton_euler, pivot_floor, Terms,
};
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input, Program};

use crate::programs::method::two;
pub use crate::programs::method::Method;
use crate::trig::Angle;

/// Everything derived for one arm, ready to emit.
///
/// `C` is the coefficient ring: [`Rational`] for an arm whose values are all literals,
/// [`Poly`](crate::poly::Poly) for one with run-time parameters.
#[derive(Clone, Debug)]
pub struct Derived<C = Rational> {
    /// The arm.
    pub arm: ArmSpec<C>,
    /// Its equations of motion.
    pub dynamics: Dynamics<C>,
    /// Its kinematics.
    pub kinematics: Kinematics<C>,
    /// The chosen programs of M, c and g, which forward dynamics reuses.
    chosen: [std::cell::OnceCell<Method>; 3],
    /// M from the expanded formulas, and the bias's unrolled recursion: candidates of more
    /// than one method, built once.
    expanded_mass_matrix: std::cell::OnceCell<Method>,
    expanded_bias: std::cell::OnceCell<Method>,
    recursive_bias: std::cell::OnceCell<Method>,
}

impl<C: Emit> Derived<C> {
    /// Derives dynamics and kinematics of the arm.
    #[must_use]
    pub fn new(arm: &ArmSpec<C>) -> Self {
        Self {
            dynamics: Dynamics::derive(arm),
            kinematics: Kinematics::derive(arm),
            arm: arm.clone(),
            chosen: Default::default(),
            expanded_mass_matrix: std::cell::OnceCell::new(),
            expanded_bias: std::cell::OnceCell::new(),
            recursive_bias: std::cell::OnceCell::new(),
        }
    }

    fn n(&self) -> usize {
        self.arm.links.len()
    }

    /// Whether expanded formulas of `terms` terms can beat `rival`. Their programs share
    /// products between rows, so their cost is below the term count, but not far below: at
    /// least 0.36 of it for arms of up to ten links (M and the torques, op counts in
    /// docs/performance.md). From four links on, formulas of more than 2.75 times the rival's
    /// cost in terms cannot win and are not built: building them dominated the derive's time
    /// for long arms, and still cost a twentieth of a 6-link arm's expansion when the bound was
    /// twice the rival's cost per link (the emitted code of 29 arms of 1 to 10 links, literal,
    /// with parameters, prismatic joints and payloads, is byte-identical under either bound).
    fn worth_expanding(&self, terms: usize, rival: &Method) -> bool {
        let n = self.n();
        n < 4 || terms * 4 <= 11 * cost(rival)
    }

    /// Terms counted by their coefficients' parts: with run-time parameters each part of a
    /// coefficient is its own product in the expanded program.
    fn terms(exprs: &[&Expr<C>]) -> usize {
        exprs
            .iter()
            .flat_map(|e| e.terms())
            .map(|(_, _, c)| c.part_count().max(1))
            .sum()
    }

    fn mass_matrix_terms(&self) -> usize {
        let m = &self.dynamics.mass_matrix;
        (0..self.n())
            .map(|i| Self::terms(&m[i][i..].iter().collect::<Vec<_>>()))
            .sum()
    }

    fn bias_terms(&self) -> usize {
        let d = &self.dynamics;
        Self::terms(&d.coriolis.iter().chain(&d.gravity).collect::<Vec<_>>())
    }
}

/// The estimated run time of a method's program, in units of one multiplication: the
/// operations (a division costs about four multiplications, a `sin_cos` call about twenty) plus
/// the longest chain of dependent operations (latency the out-of-order core cannot hide).
/// The chain is weighted one: weighted two, the expanded three-link torques beat the
/// Newton-Euler recursion on paper but measured slower (docs/performance.md).
pub(crate) fn cost(m: &Method) -> usize {
    let count = m.op_count();
    count.mul + count.add + 4 * count.div + 20 * count.sin_cos + m.depth()
}

/// The cheapest candidate by [`cost`]; the first one on a tie (candidates are listed with the
/// term-by-term form first, so that form is kept when nothing beats it).
pub(crate) fn cheapest(candidates: Vec<Method>) -> Method {
    let mut best: Option<(usize, Method)> = None;
    for m in candidates {
        let c = cost(&m);
        if best.as_ref().is_none_or(|(b, _)| c < *b) {
            best = Some((c, m));
        }
    }
    best.expect("at least one candidate").1
}

/// The straight-line program of each generated method.
impl<C: Emit> Derived<C> {
    /// `M(q)`: the cheaper (by [`OpCount`](crate::slp::OpCount)) of the expanded entries and an unrolled
    /// composite-rigid-body recursion. Upper triangle; the lower one is the same nodes.
    #[must_use]
    pub fn mass_matrix_method(&self) -> Method {
        self.chosen[0]
            .get_or_init(|| {
                let composite = self.mass_matrix_composite_method();
                if self.worth_expanding(self.mass_matrix_terms(), &composite) {
                    cheapest(vec![self.mass_matrix_expanded_method(), composite])
                } else {
                    composite
                }
            })
            .clone()
    }

    /// `M(q)` evaluated entry by entry from the expanded formulas.
    #[must_use]
    pub fn mass_matrix_expanded_method(&self) -> Method {
        self.expanded_mass_matrix
            .get_or_init(|| {
                let mut p = Program::new();
                let m = expanded_mass_matrix(&mut p, &self.dynamics);
                Method::new(p, matrix_outputs(&m))
            })
            .clone()
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
        self.chosen[1]
            .get_or_init(|| {
                let recursive = self.newton_euler_method("cor", Terms::CORIOLIS);
                let terms = Self::terms(&self.dynamics.coriolis.iter().collect::<Vec<_>>());
                if self.worth_expanding(terms, &recursive) {
                    cheapest(vec![
                        self.vector_method("cor", &self.dynamics.coriolis),
                        recursive,
                    ])
                } else {
                    recursive
                }
            })
            .clone()
    }

    /// `g(q)`: the cheaper of the expanded formulas and an unrolled static recursion.
    #[must_use]
    pub fn gravity_method(&self) -> Method {
        self.chosen[2]
            .get_or_init(|| {
                cheapest(vec![
                    self.vector_method("g", &self.dynamics.gravity),
                    self.newton_euler_method("g", Terms::GRAVITY),
                ])
            })
            .clone()
    }

    /// The bias `h(q, qd) = c + g + f`, everything but the inertial term: the cheaper of the
    /// expanded formulas and an unrolled Newton-Euler recursion (no accelerations), plus
    /// friction.
    #[must_use]
    pub fn bias_method(&self) -> Method {
        let recursive = self.with_friction(self.bias_recursive_method());
        if self.worth_expanding(self.bias_terms(), &recursive) {
            cheapest(vec![
                self.with_friction(self.expanded_bias_method()),
                recursive,
            ])
        } else {
            recursive
        }
    }

    fn expanded_bias_method(&self) -> Method {
        self.expanded_bias
            .get_or_init(|| {
                let mut p = Program::new();
                let h = self.expanded_bias(&mut p);
                let outputs = vector_outputs("h", h);
                Method::new(p, outputs)
            })
            .clone()
    }

    /// `c + g` from the expanded formulas.
    fn expanded_bias(&self, p: &mut Program) -> Vec<Id> {
        (0..self.n())
            .map(|i| {
                let e = self.dynamics.coriolis[i].add(&self.dynamics.gravity[i]);
                p.expr(&e)
            })
            .collect()
    }

    /// The bias without friction by the unrolled Newton-Euler recursion.
    fn bias_recursive_method(&self) -> Method {
        self.recursive_bias
            .get_or_init(|| self.newton_euler_method("h", Terms::BIAS))
            .clone()
    }

    /// `M(q)` and `h(q, qd) = c + g + f` in one program: one `sin_cos` per joint, and every
    /// subexpression the two share (rotations, products of parameters) computed once. The
    /// cheapest of the expanded and recursive forms of each, chosen together.
    ///
    /// A program holding the expanded M costs at least what the expanded M alone costs (its
    /// operations are among the program's, its chain of dependent operations too), so when
    /// that alone costs more than the all-recursive program, no program with it can win and
    /// none is built; likewise for the expanded bias.
    #[must_use]
    pub fn mass_matrix_and_bias_method(&self) -> Method {
        let joint = |composite: bool, recursive: bool| {
            let mut p = Program::new();
            let m = if composite {
                composite_mass_matrix(&mut p, &self.arm)
            } else {
                expanded_mass_matrix(&mut p, &self.dynamics)
            };
            let h = if recursive {
                newton_euler(&mut p, &self.arm, Terms::BIAS)
            } else {
                self.expanded_bias(&mut p)
            };
            let f = self.friction_nodes(&mut p);
            let mut outputs = matrix_outputs(&m);
            for (i, (h, f)) in h.into_iter().zip(f).enumerate() {
                outputs.push((format!("h{}", i + 1), p.add(h, f)));
            }
            let how = match (composite, recursive) {
                (false, false) => String::new(),
                (c, r) => format!(
                    "M {}, h {}.",
                    if c {
                        "by the composite-rigid-body algorithm unrolled for this arm"
                    } else {
                        "from the formulas"
                    },
                    if r {
                        "by the recursive Newton-Euler algorithm unrolled for this arm"
                    } else {
                        "from the formulas"
                    }
                ),
            };
            Method::new(p, outputs).described(&how)
        };
        let recursive = joint(true, true);
        let bound = cost(&recursive);
        let expand_m = self.worth_expanding(
            self.mass_matrix_terms(),
            &self.mass_matrix_composite_method(),
        ) && cost(&self.mass_matrix_expanded_method()) <= bound;
        let expand_h = self.worth_expanding(self.bias_terms(), &self.bias_recursive_method())
            && cost(&self.expanded_bias_method()) <= bound;
        // The term-by-term forms first, so that they are kept on a tie.
        let mut candidates = Vec::new();
        for (composite, recursive) in [(false, false), (false, true), (true, false)] {
            if (composite || expand_m) && (recursive || expand_h) {
                candidates.push(joint(composite, recursive));
            }
        }
        candidates.push(recursive);
        cheapest(candidates)
    }

    /// `tau = M qdd + c + g`: the cheaper of the expanded Lagrangian torques and an unrolled
    /// Newton-Euler recursion.
    #[must_use]
    pub fn inverse_dynamics_method(&self) -> Method {
        let recursive = self.inverse_dynamics_newton_euler_method();
        let terms = self.dynamics.torque_terms(|c| c.part_count().max(1));
        if self.worth_expanding(terms, &recursive) {
            cheapest(vec![self.inverse_dynamics_lagrange_method(), recursive])
        } else {
            recursive
        }
    }

    /// `tau` from the expanded Lagrangian torques, term by term, plus friction.
    #[must_use]
    pub fn inverse_dynamics_lagrange_method(&self) -> Method {
        self.with_friction(self.vector_method("tau", &self.dynamics.torques()))
    }

    /// `tau` by the planar recursive Newton-Euler algorithm unrolled for this arm, plus
    /// friction.
    #[must_use]
    pub fn inverse_dynamics_newton_euler_method(&self) -> Method {
        self.with_friction(self.newton_euler_method("tau", Terms::ALL))
    }

    fn newton_euler_method(&self, name: &str, terms: Terms) -> Method {
        let mut p = Program::new();
        let tau = newton_euler(&mut p, &self.arm, terms);
        let outputs = vector_outputs(name, tau);
        Method::new(p, outputs).described(RNEA)
    }

    /// `C(q, qd)`, Christoffel's: for arms whose joints all turn, by the absolute angles'
    /// route of [`crate::christoffel`] (the expanded entries are built and compared only for
    /// fewer than four links, where they can be cheaper); the expanded entries otherwise.
    #[must_use]
    pub fn coriolis_matrix_method(&self) -> Method {
        let Some(d) =
            crate::christoffel::absolute_derivatives(&self.arm, &self.dynamics.mass_matrix)
        else {
            return self.coriolis_matrix_expanded_method();
        };
        let absolute = self.coriolis_matrix_absolute_method(&d);
        if self.n() < 4 {
            cheapest(vec![self.coriolis_matrix_expanded_method(), absolute])
        } else {
            absolute
        }
    }

    /// `C(q, qd)` entry by entry from the expanded formulas.
    #[must_use]
    pub fn coriolis_matrix_expanded_method(&self) -> Method {
        let cm = self.dynamics.coriolis_matrix();
        let mut p = Program::new();
        let mut outputs = Vec::new();
        for (i, row) in cm.iter().enumerate() {
            for (j, e) in row.iter().enumerate() {
                let id = p.expr(e);
                outputs.push((format!("cm{}", two(i, j)), id));
            }
        }
        Method::new(p, outputs)
    }

    /// `C(q, qd) = J^T Ct J` in the links' absolute angles, from `D` of
    /// [`crate::christoffel::absolute_derivatives`].
    fn coriolis_matrix_absolute_method(&self, d: &[Vec<Expr<C>>]) -> Method {
        let n = self.n();
        let mut p = Program::new();
        let c = crate::christoffel::absolute_program(&mut p, d);
        let outputs = (0..n * n)
            .map(|k| (format!("cm{}", two(k / n, k % n)), c[k]))
            .collect();
        Method::new(p, outputs).described(
            "Evaluated in the links' absolute angles, where each entry of C is a sum of \
             products `dM~_ab/dphi_b w_b` of one small derivative and one absolute rate \
             (see `planar_arm::symbolic::christoffel`).",
        )
    }

    /// `T(q, qd)`: the cheaper of the expanded energy and `qd^T M qd / 2` on
    /// [`mass_matrix_method`](Self::mass_matrix_method)'s program (the same number in exact
    /// arithmetic: T is that quadratic form in the rates). From four links on the expanded
    /// energy is built only when its term count could compete.
    #[must_use]
    pub fn kinetic_energy_method(&self) -> Method {
        self.kinetic_energy_choice().0
    }

    /// [`kinetic_energy_method`](Self::kinetic_energy_method), and whether it is the quadratic
    /// form on the mass matrix's program (then the derive emits `kinetic_energy` as a call of
    /// `mass_matrix` and the run-time crate's quadratic form: the same operations, none of them
    /// type-checked again in the user's crate). On a tie the expanded energy is kept.
    pub(crate) fn kinetic_energy_choice(&self) -> (Method, bool) {
        let quadratic = self.kinetic_energy_quadratic_method();
        let terms = Self::terms(&[&self.dynamics.kinetic_energy]);
        if self.worth_expanding(terms, &quadratic) {
            let expanded = self.vector_method(
                "kinetic",
                std::slice::from_ref(&self.dynamics.kinetic_energy),
            );
            if cost(&expanded) <= cost(&quadratic) {
                return (expanded, false);
            }
        }
        (quadratic, true)
    }

    /// `T = sum_i qd_i (M_ii qd_i / 2 + sum_{j > i} M_ij qd_j)`.
    fn kinetic_energy_quadratic_method(&self) -> Method {
        let n = self.n();
        let mass = self.mass_matrix_method();
        let mut p = mass.program;
        let m = |i: usize, j: usize| mass.outputs[i * n + j].1;
        let half = p.constant(Rational::new(1.into(), 2.into()));
        let qd: Vec<Id> = (0..n).map(|j| p.input(Input::Qd(j))).collect();
        let mut rows = Vec::with_capacity(n);
        for i in 0..n {
            let diagonal = p.mul(m(i, i), qd[i]);
            let mut terms = vec![p.mul(half, diagonal)];
            for (j, &rate) in qd.iter().enumerate().skip(i + 1) {
                terms.push(p.mul(m(i, j), rate));
            }
            // `terms` holds the diagonal term at least.
            let row = p
                .balanced_sum(&terms)
                .unwrap_or_else(|| p.constant(Rational::zero()));
            rows.push(p.mul(qd[i], row));
        }
        let t = p
            .balanced_sum(&rows)
            .unwrap_or_else(|| p.constant(Rational::zero()));
        Method::new(p, vec![("kinetic".into(), t)]).described(
            "Evaluated as `qd^T M qd / 2` on the mass matrix's program (`M` as `mass_matrix` \
             computes it).",
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

    fn vector_method(&self, name: &str, entries: &[Expr<C>]) -> Method {
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

    /// The joint friction torques `damping qd_i + frictionloss sign(qd_i)` (zero nodes for an
    /// arm without friction).
    fn friction_nodes(&self, p: &mut Program) -> Vec<Id> {
        self.arm
            .links
            .iter()
            .enumerate()
            .map(|(i, link)| {
                let qd = p.input(Input::Qd(i));
                let b = p.coefficient(&link.damping);
                let f = p.coefficient(&link.frictionloss);
                let viscous = p.mul(b, qd);
                let sign = p.sign(qd);
                let coulomb = p.mul(f, sign);
                p.add(viscous, coulomb)
            })
            .collect()
    }

    /// `f(qd)`: the joint friction torques, `damping qd_i + frictionloss sign(qd_i)`.
    #[must_use]
    pub fn friction_method(&self) -> Method {
        let mut p = Program::new();
        let f = self.friction_nodes(&mut p);
        let outputs = vector_outputs("f", f);
        Method::new(p, outputs)
    }

    /// Adds the friction torques to a torque program's outputs.
    fn with_friction(&self, mut m: Method) -> Method {
        let f = self.friction_nodes(&mut m.program);
        for ((_, id), fi) in m.outputs.iter_mut().zip(f) {
            *id = m.program.add(*id, fi);
        }
        m
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

/// The mass matrix from the expanded entries (upper triangle; the lower is the same nodes).
fn expanded_mass_matrix<C: Emit>(p: &mut Program, d: &Dynamics<C>) -> Vec<Vec<Id>> {
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
/// `name1, name2, ...` for the nodes of a vector.
fn vector_outputs(name: &str, ids: Vec<Id>) -> Vec<(String, Id)> {
    ids.into_iter()
        .enumerate()
        .map(|(i, id)| (format!("{name}{}", i + 1), id))
        .collect()
}

fn matrix_outputs(m: &[Vec<Id>]) -> Vec<(String, Id)> {
    let mut outputs = Vec::new();
    for (i, row) in m.iter().enumerate() {
        for (j, &id) in row.iter().enumerate() {
            outputs.push((format!("m{}", two(i.min(j), i.max(j))), id));
        }
    }
    outputs
}

mod derivatives;
pub(crate) mod identification;
#[cfg(test)]
mod tests;
