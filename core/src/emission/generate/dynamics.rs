//! The dynamics' methods: M, c, C, g, the friction, the bias, M and h in one pass, and the
//! inverse and forward dynamics.

use std::fmt::Write as _;

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::{Call, Context, Table};
use crate::emission::function::{matrix, vector, Fn};
use crate::emit::{formula_doc, local, long_formula_doc, EmitError, DOC_TERMS};
use crate::expr::Expr;
use crate::mechanics::Dynamics;
use crate::methods::Derived;
use crate::slp::{Emit, OpCount};

/// Pushes the dynamics' methods.
pub(super) fn methods<'a, C: Emit>(d: &'a Derived<C>, cx: &Context, table: &mut Table<'a>) {
    let (n, dy) = (cx.n, &d.dynamics);
    let methods = &mut table.programs;
    methods.push(
        Fn::new(
            "mass_matrix",
            vec![cx.q],
            cx.smat.clone(),
            mass_matrix_doc(dy),
            d.mass_matrix_method(),
            Box::new(move |ids| matrix(n, n, ids)),
        )
        .touching(cx.touch.clone()),
    );
    methods.push(Fn::new(
        "coriolis",
        vec![cx.q, cx.qd],
        cx.svec.clone(),
        formula_doc(
            "The velocity-product torques c(q, qd).",
            &rows_doc("c", &dy.coriolis),
        ),
        d.coriolis_method(),
        Box::new(vector),
    ));
    methods.push(Fn::new(
        "coriolis_matrix",
        vec![cx.q, cx.qd],
        cx.smat.clone(),
        coriolis_matrix_doc(dy),
        d.coriolis_matrix_method(),
        Box::new(move |ids| matrix(n, n, ids)),
    ));
    methods.push(Fn::new(
        "gravity",
        vec![cx.q],
        cx.svec.clone(),
        formula_doc(
            "The gravity torques g(q) = dV/dq.",
            &rows_doc("g", &dy.gravity),
        ),
        d.gravity_method(),
        Box::new(vector),
    ));
    methods.push(Fn::new(
        "friction",
        vec![cx.qd],
        cx.svec.clone(),
        friction_doc(d),
        d.friction_method(),
        Box::new(vector),
    ));
    torques(d, cx, table);
}

/// Pushes the methods of the torques: the bias, M and h in one pass, the inverse dynamics and
/// the forward dynamics.
fn torques<'a, C: Emit>(d: &'a Derived<C>, cx: &Context, table: &mut Table<'a>) {
    let (n, dy) = (cx.n, &d.dynamics);
    table.programs.push(Fn::new(
        "bias",
        vec![cx.q, cx.qd],
        cx.svec.clone(),
        "The bias h(q, qd) = c + g + f: every torque but the inertial one, so that \
         `inverse_dynamics(q, qd, qdd) = mass_matrix(q) qdd + bias(q, qd)` (Pinocchio's \
         `nonLinearEffects`, MuJoCo's `qfrc_bias` plus its passive joint friction)."
            .to_string(),
        d.bias_method(),
        Box::new(vector),
    ));
    let (smat, svec) = (&cx.smat, &cx.svec);
    let mass_matrix_and_bias = d.mass_matrix_and_bias_method();
    let mh = mass_matrix_and_bias.op_count();
    table.programs.push(Fn::new(
        "mass_matrix_and_bias",
        vec![cx.q, cx.qd],
        quote!((#smat, #svec)),
        "M(q) and h(q, qd) = c + g + f in one pass, sharing the trigonometry and every \
         common subexpression: what computed-torque and operational-space controllers need \
         every cycle."
            .to_string(),
        mass_matrix_and_bias,
        Box::new(move |ids| {
            let m = matrix(n, n, &ids[..n * n]);
            let h = vector(&ids[n * n..]);
            quote!((#m, #h))
        }),
    ));
    table.programs.push(Fn::new(
        "inverse_dynamics",
        vec![cx.q, cx.qd, cx.qdd],
        cx.svec.clone(),
        inverse_dynamics_doc(dy),
        d.inverse_dynamics_method(),
        Box::new(vector),
    ));
    forward_dynamics(d, cx, table, mh);
}

/// Pushes `forward_dynamics`. From three joints it calls `mass_matrix_and_bias` (whose cost is
/// `mh`) and the run-time crate's fixed-size solve ([`solved_forward_dynamics`]); one joint,
/// and two whose mass matrix holds no run-time parameter, keep their closed forms. With
/// parameters, Cramer's exact determinant is a product of two of them: masses of 1e154
/// overflow it, where the solve's pivots stay in M's own range.
fn forward_dynamics<'a, C: Emit>(
    d: &'a Derived<C>,
    cx: &Context,
    table: &mut Table<'a>,
    mh: OpCount,
) {
    let n = cx.n;
    let solved = n >= 3 || (n == 2 && !d.mass_matrix_method().program.params().is_empty());
    if solved {
        table.calls.push(Call {
            hot: true,
            render: Box::new(move |frozen| solved_forward_dynamics(d, mh, frozen)),
        });
        return;
    }
    let doc = match n {
        1 => "qdd = (tau - c - g - f) / M11.",
        _ => "qdd = M^-1 (tau - c - g - f) in closed form (Cramer's rule, det = M11 M22 - M12^2 > 0).",
    };
    table.programs.push(Fn::new(
        "forward_dynamics",
        vec![cx.q, cx.qd, cx.tau],
        cx.svec.clone(),
        doc.to_string(),
        d.forward_dynamics_method(),
        Box::new(vector),
    ));
}

/// `forward_dynamics` of an arm of three or more joints, or with `frozen = Some(slots)` its
/// variant reading the frozen block: `mass_matrix_and_bias` (whose cost is `mh`), then
/// `planar_arm::__private::forward_solve`, the `L D L^T` solve written once in the run-time
/// crate, with each pivot's floor (a constant where `M_ii` has no run-time parameters). The
/// straight-line solve this replaces was the same operations in the same order, type-checked
/// and borrow-checked twice in every user crate (docs/performance.md).
fn solved_forward_dynamics<C: Emit>(
    d: &Derived<C>,
    mh: crate::slp::OpCount,
    frozen: Option<usize>,
) -> Result<TokenStream, EmitError> {
    let n = d.arm.links.len();
    let nn = Literal::usize_unsuffixed(n);
    let fixed: Vec<_> = (0..n)
        .map(|i| crate::programs::unrolled::fixed_pivot_floor(&d.dynamics.mass_matrix[i][i]))
        .collect();
    let floors = fixed
        .iter()
        .map(|f| match f {
            Some(f) => {
                let f = crate::emit::f64_argument_tokens(f)?;
                Ok(quote!(::planar_arm::__private::Floor::Fixed(#f)))
            }
            None => Ok(quote!(::planar_arm::__private::Floor::Relative)),
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let relative = fixed.iter().filter(|f| f.is_none()).count();
    let cost = mh + crate::programs::unrolled::ldlt_solve_cost(n, relative);
    let v = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    let (q, qd, tau) = (local("q"), local("qd"), local("tau"));
    let (m, h) = (local("m"), local("h"));
    let (name, block, call, doc) = match frozen {
        None => (
            quote!(forward_dynamics),
            TokenStream::new(),
            quote!(self.mass_matrix_and_bias(#q, #qd)),
            format!(
                "qdd = M^-1 (tau - h): M and h = c + g + f from `mass_matrix_and_bias` (one pass), \
                 then an L D L^T factorisation of M (no square roots, no allocation) by planar_arm's \
                 fixed-size solve, which the compiler unrolls for this arm. Each pivot is floored at \
                 2^-52 times a bound on M_ii (or M_ii itself where it holds run-time parameters), \
                 so an ill-conditioned M gives finite accelerations, never infinite or NaN ones.\n\n\
                 Cost: {cost}."
            ),
        ),
        Some(slots) => {
            let (b, slots) = (local("block"), Literal::usize_unsuffixed(slots));
            (
                quote!(__forward_dynamics_frozen),
                quote!(#b: &::planar_arm::__private::Block<#slots>,),
                quote!(self.__mass_matrix_and_bias_frozen(#b, #q, #qd)),
                "`forward_dynamics` with `mass_matrix_and_bias` reading the parameter-only \
                 values from a block computed by `__freeze`."
                    .to_string(),
            )
        }
    };
    let hidden = frozen.map(|_| quote!(#[doc(hidden)]));
    Ok(quote! {
        #[doc = #doc]
        #hidden
        #[inline]
        fn #name<__T: ::planar_arm::Real>(&self, #block #q: &#v, #qd: &#v, #tau: &#v) -> #v {
            let (#m, #h) = #call;
            ::planar_arm::__private::forward_solve(&#m, #tau, &#h, [#(#floors),*])
        }
    })
}

fn rows_doc<'a, C>(prefix: &str, entries: &'a [Expr<C>]) -> Vec<(String, &'a Expr<C>)> {
    entries
        .iter()
        .enumerate()
        .map(|(i, e)| (format!("{prefix}{}", i + 1), e))
        .collect()
}

/// The conventions of the printed formulas, which the first method's doc states.
const CONVENTIONS: &str = "Joint angles `q`, rates `qd`, accelerations `qdd` (1-based in the \
                           formulas); `cK` and `sK...` are the cosine and sine of the sum of the \
                           joint angles named by the digits.";

fn mass_matrix_doc<C: Emit>(dy: &Dynamics<C>) -> String {
    let n = dy.n;
    let mut rows = Vec::new();
    for i in 0..n {
        for j in i..n {
            rows.push((format!("M{}{}", i + 1, j + 1), &dy.mass_matrix[i][j]));
        }
    }
    formula_doc(
        &format!(
            "The mass matrix M(q), derived exactly (symmetric; upper triangle shown). {CONVENTIONS}"
        ),
        &rows,
    )
}

/// The expanded C is built only to be printed: the method does not need it (see
/// `christoffel`), and for long arms it is far past what the docs print (each entry has about
/// n times the terms of an entry of M).
fn coriolis_matrix_doc<C: Emit>(dy: &Dynamics<C>) -> String {
    let title = "The Coriolis matrix from Christoffel symbols, C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k.";
    let m_terms: usize = dy.mass_matrix.iter().flatten().map(Expr::len).sum();
    let cm = if m_terms * dy.n <= DOC_TERMS {
        dy.coriolis_matrix()
    } else {
        Vec::new()
    };
    if cm.is_empty() {
        return format!(
            "{title}\n\nThe exact formulas are too long to print here; \
             `planar_arm::symbolic::Dynamics::coriolis_matrix` (feature `symbolic`) \
             expands them."
        );
    }
    let mut rows = Vec::new();
    for (i, row) in cm.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            rows.push((format!("C{}{}", i + 1, j + 1), e));
        }
    }
    formula_doc(title, &rows)
}

fn friction_doc<C: Emit>(d: &Derived<C>) -> String {
    let mut doc = "The joint friction torques f(qd): viscous `damping qd_i` plus Coulomb \
                   `frictionloss sign(qd_i)`, with sign(0) = 0 (MuJoCo's `damping` and \
                   `frictionloss`). The Coulomb term jumps at `qd_i = 0`.\n\n```text\n"
        .to_string();
    for (i, l) in d.arm.links.iter().enumerate() {
        let mut terms = Vec::new();
        if !l.damping.is_zero() {
            terms.push(format!("{} qd{}", l.damping, i + 1));
        }
        if !l.frictionloss.is_zero() {
            terms.push(format!("{} sign(qd{})", l.frictionloss, i + 1));
        }
        if terms.is_empty() {
            terms.push("0".into());
        }
        let _ = writeln!(doc, "f{} = {}", i + 1, terms.join(" + "));
    }
    doc.push_str("```\n");
    doc
}

/// The torques' formulas, built only if they will be printed: a long arm's torques count
/// millions of terms.
fn inverse_dynamics_doc<C: Emit>(dy: &Dynamics<C>) -> String {
    let title = "Lagrange's equation, tau_i = d/dt dL/dqd_i - dL/dq_i, expanded, plus the \
                 joint friction f(qd) (see `friction`).";
    match dy.torque_terms(|_| 1) {
        terms if terms <= DOC_TERMS => formula_doc(title, &rows_doc("tau", &dy.torques())),
        terms => long_formula_doc(title, terms),
    }
}
