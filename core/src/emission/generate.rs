//! The `impl PlanarArm<N>` that `#[derive(PlanarArm)]` emits, assembled from the rendered
//! methods of [`emit`](crate::emit).

use std::fmt::Write as _;

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emit::{
    check_representable, coefficient_tokens, f64_tokens, formula_doc, local, render, EmitError,
    Scalar,
};
use crate::expr::Expr;
use crate::mechanics::JointKind;
use crate::methods::{Derived, Method};
use crate::paths::{F64, STR};
use crate::slp::Emit;
use crate::slp::Input;

pub use super::header::Header;
#[doc(no_inline)]
pub use crate::closed_forms::closed_forms;

use super::function::{calls_frozen, emit_fn, matrix, vector, Fn, Param};

/// The methods that get a variant reading a frozen block (see [`crate::frozen`]): what
/// simulators and controllers call every cycle.
const HOT: [&str; 5] = [
    "mass_matrix",
    "bias",
    "mass_matrix_and_bias",
    "inverse_dynamics",
    "forward_dynamics",
];

/// A hot method of an arm with run-time parameters as the parameter-only values its frozen
/// variant `m` reads (computed from the fields, the block's other slots 0.0) followed by a
/// call of that variant: the state-dependent code is written once, in `__NAME_frozen`,
/// instead of twice.
fn frozen_wrapper(
    n: usize,
    f: &Fn<'_>,
    m: &Method,
    block: &Method,
) -> Result<TokenStream, EmitError> {
    let outs: Vec<crate::slp::Id> = m.outputs.iter().map(|o| o.1).collect();
    let uses = m.program.use_counts(&outs);
    let read: std::collections::BTreeSet<usize> = m
        .program
        .nodes()
        .iter()
        .zip(&uses)
        .filter_map(|(node, &u)| match node {
            crate::slp::Node::Input(Input::Frozen(k)) if u > 0 => Some(*k),
            _ => None,
        })
        .collect();
    let part = Method {
        program: block.program.clone(),
        outputs: read.iter().map(|&k| block.outputs[k].clone()).collect(),
        evaluation: String::new(),
    };
    let rendered = render(&part, Scalar::F64)?;
    let mut values = rendered.outputs.iter();
    let slots = (0..block.outputs.len()).map(|k| {
        if read.contains(&k) {
            let v = values.next();
            quote!(#v)
        } else {
            quote!(0.0)
        }
    });
    let statements = &rendered.statements;
    let cost = m.op_count() + part.op_count();
    let evaluation = if f.method.evaluation.is_empty() {
        String::new()
    } else {
        format!("{}\n\n", f.method.evaluation)
    };
    let doc = format!("{}\n\n{evaluation}Cost: {cost}.", f.doc);
    let name = quote::format_ident!("{}", f.name);
    let frozen = quote::format_ident!("__{}_frozen", f.name);
    let nn = Literal::usize_unsuffixed(n);
    let args = f
        .params
        .iter()
        .map(|p| match *p {
            Param::Joints(name, _) => Ok(local(name)),
            Param::Force | Param::Torque => Err(EmitError {
                message: format!("internal: `{}` is frozen but takes a tip load", f.name),
            }),
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let ret = &f.ret;
    let touch = &f.touch;
    let b = local("block");
    Ok(quote! {
        #[doc = #doc]
        #[inline]
        fn #name<__T: ::planar_arm::Real>(
            &self, #(#args: &::planar_arm::nalgebra::SVector<__T, #nn>),*
        ) -> #ret {
            #touch
            #(#statements)*
            let #b = ::planar_arm::__private::Block([#(#slots),*]);
            self.#frozen(&#b, #(#args),*)
        }
    })
}

/// `kinetic_energy` as `qd^T M qd / 2` with `M` from `mass_matrix`:
/// `planar_arm::__private::kinetic_energy` performs the operations that `quadratic` (the
/// quadratic form on the mass matrix's program) appends to M's, so the cost printed is that
/// program's.
fn quadratic_kinetic_energy(n: usize, doc: &str, quadratic: &Method) -> TokenStream {
    let nn = Literal::usize_unsuffixed(n);
    let v = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    let (q, qd) = (local("q"), local("qd"));
    let doc = format!(
        "{doc}\n\nEvaluated as `qd^T M qd / 2` with M from `mass_matrix` (cheaper than the \
         formula for this arm).\n\nCost: {}.",
        quadratic.op_count()
    );
    quote! {
        #[doc = #doc]
        #[inline]
        fn kinetic_energy<__T: ::planar_arm::Real>(&self, #q: &#v, #qd: &#v) -> __T {
            ::planar_arm::__private::kinetic_energy(&self.mass_matrix(#q), #qd)
        }
    }
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

/// `::planar_arm::__private::terms(b"...", __NAMES)`: the sum in the compact encoding of
/// [`crate::compact`], its parameters named by index into the `EXACT` block's name table.
fn exact_terms<C: Emit>(e: &Expr<C>, names: &mut Vec<String>) -> Result<TokenStream, EmitError> {
    let code = Literal::byte_string(&crate::compact::encode(e, names)?);
    let table = local("NAMES");
    Ok(quote!(::planar_arm::__private::terms(#code, #table)))
}

/// `::planar_arm::Model { ... }` with the arm's values, read from `self` where they are
/// run-time parameters.
fn model_tokens<C: Emit>(d: &Derived<C>) -> Result<TokenStream, EmitError> {
    let v = coefficient_tokens::<C>;
    let vec2 = |c: &(C, C)| -> Result<TokenStream, EmitError> {
        let (x, y) = (v(&c.0)?, v(&c.1)?);
        Ok(quote!(::planar_arm::nalgebra::Vector2::new(#x, #y)))
    };
    let links = d
        .arm
        .links
        .iter()
        .map(|l| {
            let (length, mass, inertia, com) =
                (v(&l.length)?, v(&l.mass)?, v(&l.inertia)?, vec2(&l.com)?);
            let (armature, damping, frictionloss) =
                (v(&l.armature)?, v(&l.damping)?, v(&l.frictionloss)?);
            let joint = match l.joint {
                JointKind::Revolute => quote!(::planar_arm::Joint::Revolute),
                JointKind::Prismatic => quote!(::planar_arm::Joint::Prismatic),
            };
            let range = match &l.range {
                None => quote!(::core::option::Option::None),
                Some((lo, hi)) => {
                    let (lo, hi) = (f64_tokens(lo)?, f64_tokens(hi)?);
                    quote!(::core::option::Option::Some((#lo, #hi)))
                }
            };
            Ok(quote!(::planar_arm::Link {
                length: #length, mass: #mass, inertia: #inertia, com: #com,
                armature: #armature, damping: #damping, frictionloss: #frictionloss,
                joint: #joint, range: #range,
            }))
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let gravity = v(&d.arm.gravity)?;
    let payload = match &d.arm.payload {
        None => quote!(::planar_arm::Payload::NONE),
        Some(p) => {
            let (mass, inertia, com) = (v(&p.mass)?, v(&p.inertia)?, vec2(&p.com)?);
            quote!(::planar_arm::Payload { mass: #mass, inertia: #inertia, com: #com })
        }
    };
    Ok(quote!(::planar_arm::Model { links: [#(#links),*], gravity: #gravity, payload: #payload }))
}

fn rows_doc<'a, C>(prefix: &str, entries: &'a [Expr<C>]) -> Vec<(String, &'a Expr<C>)> {
    entries
        .iter()
        .enumerate()
        .map(|(i, e)| (format!("{prefix}{}", i + 1), e))
        .collect()
}

/// The complete `impl ::planar_arm::PlanarArm<N>` for the arm.
///
/// # Errors
/// If a derived constant does not fit in `f64` or in the `i128` of the exact `const` data.
#[allow(clippy::too_many_lines)] // one block per generated method, kept side by side
pub fn generate<C: Emit>(d: &Derived<C>, header: &Header) -> Result<TokenStream, EmitError> {
    check_representable(d)?;
    let n = d.arm.links.len();
    let nn = Literal::usize_unsuffixed(n);
    let dy = &d.dynamics;
    let q = Param::Joints("q", Input::Q);
    let qd = Param::Joints("qd", Input::Qd);
    let qdd = Param::Joints("qdd", Input::Qdd);
    let tau = Param::Joints("tau", Input::Tau);
    let svec = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    let smat = quote!(::planar_arm::nalgebra::SMatrix<__T, #nn, #nn>);
    let fields = &header.fields;
    let touch = if fields.is_empty() {
        TokenStream::new()
    } else {
        quote!(let _ = (#(&self.#fields),*);)
    };

    let mut m_rows = Vec::new();
    for i in 0..n {
        for j in i..n {
            m_rows.push((format!("M{}{}", i + 1, j + 1), &dy.mass_matrix[i][j]));
        }
    }
    // The expanded C is built only to be printed: the method does not need it (see
    // `christoffel`), and for long arms it is far past what the docs print (each entry has
    // about n times the terms of an entry of M).
    let m_terms: usize = dy.mass_matrix.iter().flatten().map(Expr::len).sum();
    let cm = if m_terms * n <= crate::emit::DOC_TERMS {
        dy.coriolis_matrix()
    } else {
        Vec::new()
    };
    let mut cm_rows = Vec::new();
    for (i, row) in cm.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            cm_rows.push((format!("C{}{}", i + 1, j + 1), e));
        }
    }
    let cm_title = "The Coriolis matrix from Christoffel symbols, C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k.";
    let conventions = "Joint angles `q`, rates `qd`, accelerations `qdd` (1-based in the formulas); \
                       `cK` and `sK...` are the cosine and sine of the sum of the joint angles named by the digits.";
    let mut specs = Vec::new();
    specs.push(Fn {
        name: "mass_matrix",
        generic: true,
        params: vec![q],
        ret: smat.clone(),
        doc: formula_doc(&format!("The mass matrix M(q), derived exactly (symmetric; upper triangle shown). {conventions}"), &m_rows),
        method: d.mass_matrix_method(),
        touch: touch.clone(),
        finish: Box::new(|ids| matrix(n, n, ids)),
    });
    specs.push(Fn {
        name: "coriolis",
        generic: true,
        params: vec![q, qd],
        ret: svec.clone(),
        doc: formula_doc(
            "The velocity-product torques c(q, qd).",
            &rows_doc("c", &dy.coriolis),
        ),
        method: d.coriolis_method(),
        touch: TokenStream::new(),
        finish: Box::new(vector),
    });
    specs.push(Fn {
        name: "coriolis_matrix",
        generic: true,
        params: vec![q, qd],
        ret: smat.clone(),
        doc: if cm.is_empty() {
            format!(
                "{cm_title}\n\nThe exact formulas are too long to print here; \
                 `planar_arm::symbolic::Dynamics::coriolis_matrix` (feature `symbolic`) \
                 expands them."
            )
        } else {
            formula_doc(cm_title, &cm_rows)
        },
        method: d.coriolis_matrix_method(),
        touch: TokenStream::new(),
        finish: Box::new(|ids| matrix(n, n, ids)),
    });
    specs.push(Fn {
        name: "gravity",
        generic: true,
        params: vec![q],
        ret: svec.clone(),
        doc: formula_doc(
            "The gravity torques g(q) = dV/dq.",
            &rows_doc("g", &dy.gravity),
        ),
        method: d.gravity_method(),
        touch: TokenStream::new(),
        finish: Box::new(vector),
    });
    let friction_rows: Vec<(String, String)> = d
        .arm
        .links
        .iter()
        .enumerate()
        .map(|(i, l)| {
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
            (format!("f{}", i + 1), terms.join(" + "))
        })
        .collect();
    let mut friction_doc = "The joint friction torques f(qd): viscous `damping qd_i` plus Coulomb \
                            `frictionloss sign(qd_i)`, with sign(0) = 0 (MuJoCo's `damping` and \
                            `frictionloss`). The Coulomb term jumps at `qd_i = 0`.\n\n```text\n"
        .to_string();
    for (name, f) in &friction_rows {
        let _ = writeln!(friction_doc, "{name} = {f}");
    }
    friction_doc.push_str("```\n");
    specs.push(Fn {
        name: "friction",
        generic: true,
        params: vec![qd],
        ret: svec.clone(),
        doc: friction_doc,
        method: d.friction_method(),
        touch: TokenStream::new(),
        finish: Box::new(vector),
    });
    specs.push(Fn {
        name: "bias",
        generic: true,
        params: vec![q, qd],
        ret: svec.clone(),
        doc: "The bias h(q, qd) = c + g + f: every torque but the inertial one, so that \
                  `inverse_dynamics(q, qd, qdd) = mass_matrix(q) qdd + bias(q, qd)` (Pinocchio's \
                  `nonLinearEffects`, MuJoCo's `qfrc_bias` plus its passive joint friction)."
            .to_string(),
        method: d.bias_method(),
        touch: TokenStream::new(),
        finish: Box::new(vector),
    });
    specs.push(Fn {
        name: "mass_matrix_and_bias",
        generic: true,
        params: vec![q, qd],
        ret: quote!((#smat, #svec)),
        doc: "M(q) and h(q, qd) = c + g + f in one pass, sharing the trigonometry and every \
                  common subexpression: what computed-torque and operational-space controllers \
                  need every cycle."
            .to_string(),
        method: d.mass_matrix_and_bias_method(),
        touch: TokenStream::new(),
        finish: Box::new(move |ids| {
            let m = matrix(n, n, &ids[..n * n]);
            let h = vector(&ids[n * n..]);
            quote!((#m, #h))
        }),
    });
    specs.push(Fn {
        name: "inverse_dynamics",
        generic: true,
        params: vec![q, qd, qdd],
        ret: svec.clone(),
        doc: {
            let title = "Lagrange's equation, tau_i = d/dt dL/dqd_i - dL/dq_i, expanded, plus the \
                 joint friction f(qd) (see `friction`).";
            // Built only if it will be printed: a long arm's torques count millions of terms.
            match dy.torque_terms(|_| 1) {
                terms if terms <= crate::emit::DOC_TERMS => {
                    formula_doc(title, &rows_doc("tau", &dy.torques()))
                }
                terms => crate::emit::long_formula_doc(title, terms),
            }
        },
        method: d.inverse_dynamics_method(),
        touch: TokenStream::new(),
        finish: Box::new(vector),
    });
    // From three joints `forward_dynamics` calls `mass_matrix_and_bias` and the run-time
    // crate's fixed-size solve (see `solved_forward_dynamics`); one joint, and two whose mass
    // matrix holds no run-time parameter, keep their closed forms. With parameters, Cramer's
    // exact determinant is a product of two of them: masses of 1e154 overflow it, where the
    // solve's pivots stay in M's own range.
    let solved = n >= 3 || (n == 2 && !d.mass_matrix_method().program.params().is_empty());
    if !solved {
        let fd_doc = match n {
            1 => "qdd = (tau - c - g - f) / M11.",
            _ => "qdd = M^-1 (tau - c - g - f) in closed form (Cramer's rule, det = M11 M22 - M12^2 > 0).",
        };
        specs.push(Fn {
            name: "forward_dynamics",
            generic: true,
            params: vec![q, qd, tau],
            ret: svec.clone(),
            doc: fd_doc.to_string(),
            method: d.forward_dynamics_method(),
            touch: TokenStream::new(),
            finish: Box::new(vector),
        });
    }
    let ke_doc = formula_doc("The kinetic energy.", &[("T".into(), &dy.kinetic_energy)]);
    let (ke, ke_quadratic) = d.kinetic_energy_choice();
    // The quadratic form on M's program is `mass_matrix` and a product the run-time crate
    // writes once (see `quadratic_kinetic_energy`).
    let ke_fn = if ke_quadratic {
        Some(quadratic_kinetic_energy(n, &ke_doc, &ke))
    } else {
        specs.push(Fn {
            name: "kinetic_energy",
            generic: true,
            params: vec![q, qd],
            ret: quote!(__T),
            doc: ke_doc,
            method: ke,
            touch: TokenStream::new(),
            finish: Box::new(|ids| {
                let i = &ids[0];
                quote!(#i)
            }),
        });
        None
    };
    specs.push(Fn {
        name: "potential_energy",
        generic: true,
        params: vec![q],
        ret: quote!(__T),
        doc: formula_doc(
            "The potential energy (zero at y = 0).",
            &[("V".into(), &dy.potential_energy)],
        ),
        method: d.potential_energy_method(),
        touch: TokenStream::new(),
        finish: Box::new(|ids| {
            let i = &ids[0];
            quote!(#i)
        }),
    });
    let ki = &d.kinematics;
    let (tx, ty) = &ki.points[n];
    specs.push(Fn {
        name: "tip_pose",
        generic: false,
        params: vec![q],
        ret: quote!(::planar_arm::nalgebra::Isometry2<#F64>),
        doc: formula_doc(
            &format!(
                "The tip pose; the orientation is the last link's angle {}.",
                ki.tip_angle
            ),
            &[("x".into(), tx), ("y".into(), ty)],
        ),
        method: d.tip_pose_method(),
        touch: TokenStream::new(),
        finish: Box::new(|ids| {
            let (x, y, c, s) = (&ids[0], &ids[1], &ids[2], &ids[3]);
            quote!(::planar_arm::__private::pose(#x, #y, #c, #s))
        }),
    });
    let mut j_rows = Vec::new();
    for (r, row) in ki.jacobian.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            j_rows.push((format!("J{}{}", r + 1, j + 1), e));
        }
    }
    specs.push(Fn {
        name: "jacobian",
        generic: true,
        params: vec![q],
        ret: quote!(::planar_arm::nalgebra::SMatrix<__T, 3, #nn>),
        doc: formula_doc("The Jacobian d(x, y, phi)/dq.", &j_rows),
        method: d.jacobian_method(),
        touch: TokenStream::new(),
        finish: Box::new(|ids| matrix(3, n, ids)),
    });
    specs.push(Fn {
        name: "joint_positions",
        generic: true,
        params: vec![q],
        ret: quote!([::planar_arm::nalgebra::Point2<__T>; #nn]),
        doc: "The position of each joint, joint 1 at the origin.".to_string(),
        method: d.joint_positions_method(),
        touch: TokenStream::new(),
        finish: Box::new(|ids| {
            let pts = ids.chunks(2).map(|p| {
                let (x, y) = (&p[0], &p[1]);
                quote!(::planar_arm::nalgebra::Point2::new(#x, #y))
            });
            quote!([#(#pts),*])
        }),
    });
    specs.push(Fn {
        name: "tip_polar",
        generic: false,
        params: vec![q],
        ret: quote!((#F64, #F64)),
        doc: formula_doc(
            "The tip in polar form: r from r^2 (which does not depend on q1), theta = atan2(y, x).",
            &[("r^2".into(), &ki.radius_squared)],
        ),
        method: d.tip_polar_method(),
        touch: TokenStream::new(),
        finish: Box::new(|ids| {
            let (r2, x, y) = (&ids[0], &ids[1], &ids[2]);
            quote!(::planar_arm::__private::polar(#r2, #x, #y))
        }),
    });
    specs.push(Fn {
        name: "joint_torques",
        generic: false,
        params: vec![q, Param::Force, Param::Torque],
        ret: quote!(::planar_arm::nalgebra::SVector<#F64, #nn>),
        doc: "Statics: tau = J^T (u, v, torque), the motor torques that make the tip exert force (u, v) and torque `torque`.".to_string(),
        method: d.joint_torques_method(),
        touch: TokenStream::new(),
        finish: Box::new(vector),
    });
    if let Some(method) = d.inverse_dynamics_derivatives_method() {
        let f64mat = quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>);
        specs.push(Fn {
            name: "inverse_dynamics_derivatives",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!((#f64mat, #f64mat)),
            doc:
                "The partial derivatives of `inverse_dynamics`, `(dtau/dq, dtau/dqd)` (`dtau/dqdd` \
                  is `mass_matrix`), straight-line code differentiated exactly at compile time. \
                  Coulomb friction contributes 0 to `dtau/dqd`, also at `qd_i = 0` where it jumps."
                    .to_string(),
            method,
            touch: TokenStream::new(),
            finish: Box::new(move |ids| {
                let dq = matrix(n, n, &ids[..n * n]);
                let dqd = matrix(n, n, &ids[n * n..]);
                quote!((#dq, #dqd))
            }),
        });
    }
    if let Some(method) = d.forward_dynamics_derivatives_method() {
        let f64mat = quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>);
        specs.push(Fn {
            name: "forward_dynamics_derivatives",
            generic: false,
            params: vec![q, qd, tau],
            ret: quote!((#f64mat, #f64mat, #f64mat)),
            doc:
                "The partial derivatives of `forward_dynamics`, `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, \
                  straight-line code built at compile time. Coulomb friction as in \
                  `inverse_dynamics_derivatives`."
                    .to_string(),
            method,
            touch: TokenStream::new(),
            finish: Box::new(move |ids| {
                let m = (0..3).map(|k| matrix(n, n, &ids[k * n * n..(k + 1) * n * n]));
                quote!((#(#m),*))
            }),
        });
    }

    let hot: Vec<&Fn<'_>> = specs.iter().filter(|f| HOT.contains(&f.name)).collect();
    // An all-literal arm's constants are folded already: nothing to freeze.
    let frozen = if hot.iter().any(|f| !f.method.program.params().is_empty()) {
        let methods: Vec<Method> = hot.iter().map(|f| f.method.clone()).collect();
        crate::frozen::freeze(&methods)
    } else {
        None
    };
    let mut fns = Vec::new();
    for f in &specs {
        let variant = frozen
            .as_ref()
            .filter(|_| calls_frozen(n, f.name))
            .and_then(|fz| {
                hot.iter()
                    .position(|h| h.name == f.name)
                    .map(|i| (&fz.methods[i], &fz.block))
            });
        fns.push(match variant {
            Some((m, block)) => frozen_wrapper(n, f, m, block)?,
            None => emit_fn(n, f, None)?,
        });
    }
    fns.extend(ke_fn);
    let slots = frozen.as_ref().map_or(0, |fz| fz.block.outputs.len());
    if solved {
        let mh = specs
            .iter()
            .find(|f| f.name == "mass_matrix_and_bias")
            .map(|f| f.method.op_count())
            .unwrap_or_default();
        fns.push(solved_forward_dynamics(d, mh, None)?);
        if frozen.is_some() {
            fns.push(solved_forward_dynamics(d, mh, Some(slots))?);
        }
    }
    let slots_lit = Literal::usize_unsuffixed(slots);
    fns.push(quote!(
        #[doc(hidden)]
        type __Frozen = ::planar_arm::__private::Block<#slots_lit>;
    ));
    if let Some(fz) = &frozen {
        for (f, m) in hot.iter().zip(&fz.methods) {
            fns.push(emit_fn(n, f, Some((m, slots)))?);
        }
        let rendered = render(&fz.block, Scalar::F64)?;
        let statements = &rendered.statements;
        let outputs = &rendered.outputs;
        let names: Vec<&str> = hot.iter().map(|f| f.name).collect();
        let doc = format!(
            "The parameter-only values of `{}`, from the arm's fields. Cost: {}.",
            names.join("`, `"),
            fz.block.op_count()
        );
        fns.push(quote!(
            #[doc = #doc]
            #[doc(hidden)]
            #[inline]
            fn __freeze(&self) -> ::planar_arm::__private::Block<#slots_lit> {
                #(#statements)*
                ::planar_arm::__private::Block([#(#outputs),*])
            }
        ));
    }

    let model = model_tokens(d)?;
    let mut names = Vec::new();
    let mut exact = |e: &Expr<C>| exact_terms(e, &mut names);
    let t_exact = exact(&dy.kinetic_energy)?;
    let v_exact = exact(&dy.potential_energy)?;
    let mut m_exact = Vec::new();
    for row in &dy.mass_matrix {
        let row = row.iter().map(&mut exact).collect::<Result<Vec<_>, _>>()?;
        m_exact.push(quote!([#(#row),*]));
    }
    let c_exact = dy
        .coriolis
        .iter()
        .map(&mut exact)
        .collect::<Result<Vec<_>, _>>()?;
    let g_exact = dy
        .gravity
        .iter()
        .map(&mut exact)
        .collect::<Result<Vec<_>, _>>()?;
    let table = local("NAMES");
    let names = names.iter().map(|n| n.trim_start_matches("r#"));
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    Ok(quote! {
        #[automatically_derived]
        #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
        impl #impl_generics ::planar_arm::PlanarArm<#nn> for #ty #where_clause {
            const EXACT: ::planar_arm::exact::Derivation<#nn> = {
                const #table: &[&#STR] = &[#(#names),*];
                ::planar_arm::exact::Derivation {
                    kinetic_energy: #t_exact,
                    potential_energy: #v_exact,
                    mass_matrix: [#(#m_exact),*],
                    coriolis: [#(#c_exact),*],
                    gravity: [#(#g_exact),*],
                }
            };
            #[inline]
            fn model(&self) -> ::planar_arm::Model<#nn> {
                #model
            }
            #(#fns)*
        }
    })
}

/// A readable summary of the derivation for docs: link table and Lagrangian.
#[must_use]
pub fn summary<C: Emit>(d: &Derived<C>) -> String {
    let mut s = String::new();
    for (i, l) in d.arm.links.iter().enumerate() {
        let _ = writeln!(
            s,
            "link {}: length {}, mass {}, inertia {}, com ({}, {}), armature {}, damping {}, frictionloss {}",
            i + 1,
            l.length,
            l.mass,
            l.inertia,
            l.com.0,
            l.com.1,
            l.armature,
            l.damping,
            l.frictionloss
        );
    }
    let _ = writeln!(s, "gravity {}", d.arm.gravity);
    s
}

/// A stub `impl PlanarArm<n>` whose methods are unreachable: emitted next to a compile error
/// so that uses of the trait elsewhere do not add a cascade of errors.
#[must_use]
pub fn stub(n: usize, header: &Header) -> TokenStream {
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    let nn = Literal::usize_unsuffixed(n);
    let v = quote!(&::planar_arm::nalgebra::SVector<#F64, #nn>);
    let sv = quote!(::planar_arm::nalgebra::SVector<#F64, #nn>);
    let body = quote!({ ::core::unreachable!() });
    let g = quote!(<__T: ::planar_arm::Real>);
    let vt = quote!(&::planar_arm::nalgebra::SVector<__T, #nn>);
    let mt = quote!(::planar_arm::nalgebra::SMatrix<__T, #nn, #nn>);
    let svt = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    quote! {
        #[automatically_derived]
        #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
        impl #impl_generics ::planar_arm::PlanarArm<#nn> for #ty #where_clause {
            const EXACT: ::planar_arm::exact::Derivation<#nn> = ::planar_arm::exact::Derivation {
                kinetic_energy: ::planar_arm::__private::terms(b"", &[]),
                potential_energy: ::planar_arm::__private::terms(b"", &[]),
                mass_matrix: [[::planar_arm::__private::terms(b"", &[]); #nn]; #nn],
                coriolis: [::planar_arm::__private::terms(b"", &[]); #nn],
                gravity: [::planar_arm::__private::terms(b"", &[]); #nn],
            };
            fn mass_matrix #g(&self, _: #vt) -> #mt #body
            fn coriolis #g(&self, _: #vt, _: #vt) -> #svt #body
            fn coriolis_matrix #g(&self, _: #vt, _: #vt) -> #mt #body
            fn gravity #g(&self, _: #vt) -> #svt #body
            fn friction #g(&self, _: #vt) -> #svt #body
            fn bias #g(&self, _: #vt, _: #vt) -> #svt #body
            fn mass_matrix_and_bias #g(&self, _: #vt, _: #vt) -> (#mt, #svt) #body
            type __Frozen = ::planar_arm::__private::Block<0>;
            fn model(&self) -> ::planar_arm::Model<#nn> #body
            fn inverse_dynamics #g(&self, _: #vt, _: #vt, _: #vt) -> #svt #body
            fn forward_dynamics #g(&self, _: #vt, _: #vt, _: #vt) -> #svt #body
            fn kinetic_energy #g(&self, _: #vt, _: #vt) -> __T #body
            fn potential_energy #g(&self, _: #vt) -> __T #body
            fn tip_pose(&self, _: #v) -> ::planar_arm::nalgebra::Isometry2<#F64> #body
            fn jacobian #g(&self, _: #vt) -> ::planar_arm::nalgebra::SMatrix<__T, 3, #nn> #body
            fn joint_positions #g(&self, _: #vt) -> [::planar_arm::nalgebra::Point2<__T>; #nn] #body
            fn tip_polar(&self, _: #v) -> (f64, f64) #body
            fn joint_torques(&self, _: #v, _: &::planar_arm::nalgebra::Vector2<#F64>, _: f64) -> #sv #body
        }
    }
}
