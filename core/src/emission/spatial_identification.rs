//! The `impl Identification` `#[derive(SpatialArm)]` emits: the regressor of the ten standard
//! parameters per body (`programs::spatial_regressor`), their values, and the base regressor
//! and base parameters found exactly ([`identification`](crate::methods::identification::spatial)).

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::function::{emit_fn, matrix, vector, Fn, Param};
use super::header::Header;
use crate::emit::EmitError;
use crate::mechanics::spatial::SpatialArmSpec;
use crate::methods::identification::spatial::{identification, SpatialIdentification};
use crate::methods::Method;
use crate::paths::{F64, STR};
use crate::poly::Poly;
use crate::programs::spatial_regressor::{regressor, standard_values};
use crate::slp::{Input, Program};

/// `impl ::planar_arm::Identification<N, P, B>` for a spatial arm, or nothing when its geometry
/// is not exact (see [`identification`]).
///
/// # Errors
/// If a constant does not fit in `f64`.
pub fn spatial_identification(
    arm: &SpatialArmSpec,
    header: &Header,
) -> Result<TokenStream, EmitError> {
    let Some(id) = identification(arm) else {
        return Ok(TokenStream::new());
    };
    let n = arm.joints.len();
    let (pp, bb) = (id.parameters.len(), id.base.columns.len());
    let (nn, pl, bl) = (
        Literal::usize_unsuffixed(n),
        Literal::usize_unsuffixed(pp),
        Literal::usize_unsuffixed(bb),
    );
    let names: Vec<&str> = id.parameters.iter().map(|s| s.name.as_str()).collect();
    let formulas: Vec<String> = (0..bb).map(|b| id.base.formula_named(b, &names)).collect();
    let (standard_doc, base_doc) = docs(&names, &formulas);
    let all: Vec<usize> = (0..pp).collect();
    let q = Param::Joints("q", Input::Q);
    let qd = Param::Joints("qd", Input::Qd);
    let qdd = Param::Joints("qdd", Input::Qdd);
    let specs = [
        Fn {
            name: "regressor",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #pl>),
            doc: format!("The regressor Y(q, qd, qdd): `Y * standard_parameters() == inverse_dynamics(q, qd, qdd)`. {standard_doc}"),
            method: regressor(arm, &id.parameters, &all),
            touch: TokenStream::new(),
            finish: Box::new(move |ids| matrix(n, pp, ids)),
        },
        Fn {
            name: "standard_parameters",
            generic: false,
            params: vec![],
            ret: quote!(::planar_arm::nalgebra::SVector<#F64, #pl>),
            doc: format!("The arm's standard parameters now (run-time parameters read from their fields). {standard_doc}"),
            method: values(arm, &id, false),
            touch: TokenStream::new(),
            finish: Box::new(vector),
        },
        Fn {
            name: "base_regressor",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #bl>),
            doc: format!("The base regressor: the regressor's columns of the base parameters, `Y_b * base_parameters() == inverse_dynamics(q, qd, qdd)`. {base_doc}"),
            method: regressor(arm, &id.parameters, &id.base.columns),
            touch: TokenStream::new(),
            finish: Box::new(move |ids| matrix(n, bb, ids)),
        },
        Fn {
            name: "base_parameters",
            generic: false,
            params: vec![],
            ret: quote!(::planar_arm::nalgebra::SVector<#F64, #bl>),
            doc: format!("The arm's base parameters now. {base_doc}"),
            method: values(arm, &id, true),
            touch: TokenStream::new(),
            finish: Box::new(vector),
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
        #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
        impl #impl_generics ::planar_arm::Identification<#nn, #pl, #bl> for #ty #where_clause {
            const PARAMETERS: [&'static #STR; #pl] = [#(#names),*];
            const BASE_PARAMETERS: [&'static #STR; #bl] = [#(#formulas),*];
            #(#fns)*
        }
    })
}

/// The standard parameters' values, or with `base` the base parameters': each grouping's
/// exact combination of them.
fn values(arm: &SpatialArmSpec, id: &SpatialIdentification, base: bool) -> Method {
    let standard = standard_values(arm, &id.parameters);
    let mut p = Program::new();
    let outputs = if base {
        id.base
            .grouping
            .iter()
            .enumerate()
            .map(|(b, group)| {
                let value = group.iter().fold(Poly::default(), |acc, (k, c)| {
                    acc + standard[*k].clone() * Poly::constant(c.clone())
                });
                (format!("b{}", b + 1), p.poly(&value))
            })
            .collect()
    } else {
        standard
            .iter()
            .zip(&id.parameters)
            .map(|(v, s)| (s.name.clone(), p.poly(v)))
            .collect()
    };
    Method::new(p, outputs)
}

/// The lists of the standard and base parameters the methods' docs end with.
fn docs(names: &[&str], formulas: &[String]) -> (String, String) {
    let listing = |rows: Vec<String>| -> String {
        rows.iter()
            .enumerate()
            .map(|(k, r)| format!("{}. `{r}`\n", k + 1))
            .collect()
    };
    let standard = format!(
        "The standard parameters, in column order: per link, in Pinocchio's order, the mass `m` \
         (kg), the first moments `mx`, `my`, `mz` (m c in the link's frame, kg m) and the inertia \
         about the link frame's origin in its axes `xx`, `xy`, `yy`, `xz`, `yz`, `zz` (kg m^2); \
         per joint that has them armature `ia`, damping `fv` and Coulomb friction `fc`; then the \
         payload's ten in the tool frame (`mp`, ..., `zzp`):\n\n{}",
        listing(names.iter().map(ToString::to_string).collect())
    );
    let base = format!(
        "The base parameters, each an exact combination of the standard ones, found at compile \
         time by rational elimination on the regressor evaluated exactly at rational points:\n\n{}",
        listing(formulas.to_vec())
    );
    (standard, base)
}
