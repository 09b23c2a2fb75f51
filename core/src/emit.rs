//! Emission: straight-line Rust for a derived arm.
//!
//! Each generated method is one [`Program`]: inputs are unpacked into named locals, each
//! joint angle that is needed gets one `sin_cos` call, trig atoms of angle sums are `let`s
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
}

fn two(i: usize, j: usize) -> String {
    format!("{}{}", i + 1, j + 1)
}

/// The straight-line program of each generated method.
impl Derived {
    /// `M(q)`, upper triangle (the lower one is the same nodes).
    #[must_use]
    pub fn mass_matrix_method(&self) -> Method {
        let mut p = Program::new();
        let mut outputs = Vec::new();
        for i in 0..self.n() {
            for j in 0..self.n() {
                let (a, b) = (i.min(j), i.max(j));
                let id = p.expr(&self.dynamics.mass_matrix[a][b]);
                outputs.push((format!("m{}", two(a, b)), id));
            }
        }
        Method {
            program: p,
            outputs,
        }
    }

    /// `c(q, qd)`.
    #[must_use]
    pub fn coriolis_method(&self) -> Method {
        self.vector_method("cor", &self.dynamics.coriolis)
    }

    /// `g(q)`.
    #[must_use]
    pub fn gravity_method(&self) -> Method {
        self.vector_method("g", &self.dynamics.gravity)
    }

    /// `tau = M qdd + c + g`, in the expanded Lagrangian form.
    #[must_use]
    pub fn inverse_dynamics_method(&self) -> Method {
        self.vector_method("tau", &self.dynamics.torques)
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
        Method {
            program: p,
            outputs,
        }
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
        Method {
            program: p,
            outputs,
        }
    }

    /// `qdd = M^-1 (tau - c - g)`: Cramer's rule for one and two joints, an unrolled
    /// `L D L^T` factorisation (no square roots, one division per joint) beyond.
    #[must_use]
    pub fn forward_dynamics_method(&self) -> Method {
        let n = self.n();
        let mut p = Program::new();
        let m: Vec<Vec<Id>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| p.expr(&self.dynamics.mass_matrix[i.min(j)][i.max(j)]))
                    .collect()
            })
            .collect();
        let rhs: Vec<Id> = (0..n)
            .map(|i| {
                let bias = p.expr(&self.dynamics.coriolis[i].add(&self.dynamics.gravity[i]));
                let tau = p.input(Input::Tau(i));
                p.sub(tau, bias)
            })
            .collect();
        for (i, &r) in rhs.iter().enumerate() {
            p.set_name(r, format!("rhs{}", i + 1));
        }
        let qdd = match n {
            1 => vec![p.div(rhs[0], m[0][0])],
            2 => {
                let a = p.mul(m[0][0], m[1][1]);
                let b = p.mul(m[0][1], m[0][1]);
                let det = p.sub(a, b);
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
            _ => ldlt_solve(&mut p, &m, &rhs),
        };
        let outputs = qdd
            .into_iter()
            .enumerate()
            .map(|(i, id)| (format!("qdd{}", i + 1), id))
            .collect();
        Method {
            program: p,
            outputs,
        }
    }

    /// Tip `x, y`, then `cos` and `sin` of the last link's angle.
    #[must_use]
    pub fn tip_pose_method(&self) -> Method {
        let mut p = Program::new();
        let (x, y) = &self.kinematics.points[self.n()];
        let x = p.expr(x);
        let y = p.expr(y);
        let (c, s) = p.trig_pair(&self.kinematics.tip_angle);
        Method {
            program: p,
            outputs: vec![
                ("x".into(), x),
                ("y".into(), y),
                ("cos_phi".into(), c),
                ("sin_phi".into(), s),
            ],
        }
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
        Method {
            program: p,
            outputs,
        }
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
        Method {
            program: p,
            outputs,
        }
    }

    /// `r^2`, tip `x`, tip `y`.
    #[must_use]
    pub fn tip_polar_method(&self) -> Method {
        let mut p = Program::new();
        let r2 = p.expr(&self.kinematics.radius_squared);
        let (x, y) = &self.kinematics.points[self.n()];
        let x = p.expr(x);
        let y = p.expr(y);
        Method {
            program: p,
            outputs: vec![("r2".into(), r2), ("x".into(), x), ("y".into(), y)],
        }
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
        Method {
            program: p,
            outputs,
        }
    }
}

/// Solves `M x = b` with `M = L D L^T` unrolled.
fn ldlt_solve(p: &mut Program, m: &[Vec<Id>], b: &[Id]) -> Vec<Id> {
    let n = m.len();
    let mut l = vec![vec![None::<Id>; n]; n];
    let mut d = vec![None::<Id>; n];
    let mut inv_d = vec![None::<Id>; n];
    for j in 0..n {
        // d_j = M_jj - sum_k L_jk^2 d_k
        let mut dj = m[j][j];
        for k in 0..j {
            let ljk = l[j][k].unwrap_or(dj);
            let w = p.mul(ljk, ljk);
            let w = p.mul(w, d[k].unwrap_or(dj));
            dj = p.sub(dj, w);
        }
        p.set_name(dj, format!("d{}", j + 1));
        let one = p.constant(Rational::from_integer(1.into()));
        let inv = p.div(one, dj);
        p.set_name(inv, format!("inv_d{}", j + 1));
        d[j] = Some(dj);
        inv_d[j] = Some(inv);
        for i in j + 1..n {
            // L_ij = (M_ij - sum_k L_ik L_jk d_k) / d_j
            let mut s = m[i][j];
            for k in 0..j {
                let (lik, ljk, dk) = (
                    l[i][k].unwrap_or(s),
                    l[j][k].unwrap_or(s),
                    d[k].unwrap_or(s),
                );
                let w = p.mul(lik, ljk);
                let w = p.mul(w, dk);
                s = p.sub(s, w);
            }
            let lij = p.mul(s, inv);
            p.set_name(lij, format!("l{}", two(i, j)));
            l[i][j] = Some(lij);
        }
    }
    // L y = b
    let mut y = Vec::with_capacity(n);
    for i in 0..n {
        let mut yi = b[i];
        for (k, &yk) in y.iter().enumerate() {
            let w = p.mul(l[i][k].unwrap_or(yk), yk);
            yi = p.sub(yi, w);
        }
        y.push(yi);
    }
    // D z = y, L^T x = z
    let mut x = vec![None::<Id>; n];
    for i in (0..n).rev() {
        let mut xi = p.mul(y[i], inv_d[i].unwrap_or(y[i]));
        for k in i + 1..n {
            let xk = x[k].unwrap_or(xi);
            let w = p.mul(l[k][i].unwrap_or(xk), xk);
            xi = p.sub(xi, w);
        }
        x[i] = Some(xi);
    }
    x.into_iter().map(|v| v.unwrap_or(b[0])).collect()
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
    Ident::new(name, Span::mixed_site())
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
    for (&j, &(s, c)) in &joints {
        let q = local(&input_name(Input::Q(j)));
        let s = if s {
            local(&format!("s{}", j + 1))
        } else {
            local("_")
        };
        let c = if c {
            local(&format!("c{}", j + 1))
        } else {
            local("_")
        };
        statements.push(quote!(let (#s, #c) = #q.sin_cos();));
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
