//! The `impl Identification` the derive emits: the regressor, the standard parameters'
//! values, the base regressor and the base parameters' values, as generated methods. Their
//! programs come from [`crate::methods`], the base parameters by exact elimination from
//! [`base_parameters_from_energies`](crate::regressor::base_parameters_from_energies).

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::function::{emit_fn, matrix, vector, Fn, Param};
use super::header::Header;
use crate::emit::EmitError;
use crate::methods::Derived;
use crate::paths::{F64, STR};
use crate::slp::{Emit, Input};

pub use crate::methods::identification::Identification;

/// The longest arm that gets an `Identification` impl. The exact elimination grows about as
/// the fifth power of the links and runs unoptimised in a user's build: at 30 links the
/// user crate's clean rebuild takes 24 s with it and 16 s without (docs/performance.md),
/// inside the 90 s budget; longer chains would outgrow it.
pub const MAX_LINKS: usize = 30;

/// `impl ::planar_arm::Identification<N, P, B>` for the arm, or nothing when its lengths or
/// gravity are such that the groupings are not polynomials (see
/// [`base_parameters_from_energies`](crate::regressor::base_parameters_from_energies)), it
/// has a joint spring or more than [`MAX_LINKS`] links.
///
/// # Errors
/// If a constant does not fit in `f64`.
pub fn identification<C: Emit>(d: &Derived<C>, header: &Header) -> Result<TokenStream, EmitError> {
    // A spring's torque is known, not a parameter the torques are linear in: `Y theta` would
    // not be the inverse dynamics (as for spatial arms).
    if d.arm.links.len() > MAX_LINKS || d.arm.links.iter().any(|l| !l.stiffness.is_zero()) {
        return Ok(TokenStream::new());
    }
    let Some(id) = d.identification() else {
        return Ok(TokenStream::new());
    };
    let all: Vec<usize> = (0..id.parameters.len()).collect();
    let names: Vec<&str> = id.parameters.iter().map(|s| s.name.as_str()).collect();
    let formulas: Vec<String> = (0..id.base.columns.len())
        .map(|b| id.base.formula(b, &id.parameters))
        .collect();
    let (standard_doc, base_doc) = parameter_docs(&names, &formulas);
    identification_impl(
        d.arm.links.len(),
        header,
        &names,
        &formulas,
        [
            d.regressor_method(&id.parameters, &all),
            d.parameter_values_method(&id.parameters, None),
            d.regressor_method(&id.parameters, &id.base.columns),
            d.parameter_values_method(&id.parameters, Some(&id.base)),
        ],
        (&standard_doc, &base_doc),
    )
}

/// `impl ::planar_arm::Identification<N, P, B>` from its four methods' programs (regressor,
/// standard parameters' values, base regressor, base parameters' values), the parameters'
/// names and groupings, and the docs' lists of them. Both derives emit it.
///
/// # Errors
/// If a constant does not fit in `f64`.
pub(crate) fn identification_impl(
    n: usize,
    header: &Header,
    names: &[&str],
    formulas: &[String],
    [regressor, standard, base_regressor, base]: [crate::methods::Method; 4],
    (standard_doc, base_doc): (&str, &str),
) -> Result<TokenStream, EmitError> {
    let (pp, bb) = (names.len(), formulas.len());
    let (nn, pl, bl) = (
        Literal::usize_unsuffixed(n),
        Literal::usize_unsuffixed(pp),
        Literal::usize_unsuffixed(bb),
    );
    let q = Param::Joints("q", Input::Q);
    let qd = Param::Joints("qd", Input::Qd);
    let qdd = Param::Joints("qdd", Input::Qdd);
    // A base regressor with a packed program (spatial arms) runs through the dispatch, which
    // passes AVX2 lanes where the processor has AVX2 and FMA.
    let base_kernel = base_regressor
        .packed
        .is_some()
        .then(|| ("BaseRegressor", quote!(#nn, #pl, #bl)));
    let specs = [
        Fn {
            name: "regressor",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #pl>),
            doc: format!("The regressor Y(q, qd, qdd): `Y * standard_parameters() == inverse_dynamics(q, qd, qdd)`. {standard_doc}"),
            method: regressor,
            touch: TokenStream::new(),
            finish: Box::new(move |ids| matrix(n, pp, ids)),
            kernel: None,
            inlined_body: false,
        },
        Fn {
            name: "standard_parameters",
            generic: false,
            params: vec![],
            ret: quote!(::planar_arm::nalgebra::SVector<#F64, #pl>),
            doc: format!("The arm's standard parameters now (run-time parameters read from their fields). {standard_doc}"),
            method: standard,
            touch: TokenStream::new(),
            finish: Box::new(vector),
            kernel: None,
            inlined_body: false,
        },
        Fn {
            name: "base_regressor",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #bl>),
            doc: format!("The base regressor: the regressor's columns of the base parameters, `Y_b * base_parameters() == inverse_dynamics(q, qd, qdd)`. {base_doc}"),
            method: base_regressor,
            touch: TokenStream::new(),
            finish: Box::new(move |ids| matrix(n, bb, ids)),
            kernel: base_kernel,
            inlined_body: false,
        },
        Fn {
            name: "base_parameters",
            generic: false,
            params: vec![],
            ret: quote!(::planar_arm::nalgebra::SVector<#F64, #bl>),
            doc: format!("The arm's base parameters now. {base_doc}"),
            method: base,
            touch: TokenStream::new(),
            finish: Box::new(vector),
            kernel: None,
            inlined_body: false,
        },
    ];
    let mut fns = Vec::new();
    for f in &specs {
        fns.push(emit_fn(n, f, None)?);
    }
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    Ok(quote! {
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
        impl #impl_generics ::planar_arm::Identification<#nn, #pl, #bl> for #ty #where_clause {
            const PARAMETERS: [&'static #STR; #pl] = [#(#names),*];
            const BASE_PARAMETERS: [&'static #STR; #bl] = [#(#formulas),*];
            #(#fns)*
        }
    })
}

/// The lists of the standard and base parameters that the methods' docs end with.
fn parameter_docs(names: &[&str], formulas: &[String]) -> (String, String) {
    let listing = |rows: &[String]| -> String {
        rows.iter()
            .enumerate()
            .map(|(k, r)| format!("{}. {r}\n", k + 1))
            .collect()
    };
    let standard_doc = format!(
        "The standard parameters, in column order: per link `zz` (moment of inertia about the \
         joint, kg m^2), `mx`, `my` (first moments m cx, m cy in the link's frame, kg m), then \
         the payload's (`zzp`, `mxp`, `myp` in the last link's frame), the masses (kg), and \
         per joint that has them armature `ia` (kg m^2), damping `fv` (N m s/rad) and \
         Coulomb friction `fc` (N m):\n\n{}",
        listing(&names.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>())
    );
    let base_doc = format!(
        "The base parameters, each an exact combination of the standard ones found at compile \
         time by rational elimination on the regressor's columns:\n\n{}",
        listing(
            &formulas
                .iter()
                .map(|s| format!("`{s}`"))
                .collect::<Vec<_>>()
        )
    );
    (standard_doc, base_doc)
}
