//! The `impl Identification` `#[derive(SpatialArm)]` emits: the regressor of the ten standard
//! parameters per body (`programs::spatial_regressor`), their values, and the base regressor
//! and base parameters found exactly ([`identification`](crate::methods::identification::spatial)).

use proc_macro2::TokenStream;

use super::header::Header;
use super::identification::identification_impl;
use crate::emit::EmitError;
use crate::mechanics::spatial::SpatialArmSpec;
use crate::methods::identification::spatial::{identification, SpatialIdentification};
use crate::methods::Method;
use crate::poly::Poly;
use crate::programs::spatial_regressor::{packed_regressor, regressor, standard_values};
use crate::slp::Program;

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
    let names: Vec<&str> = id.parameters.iter().map(|s| s.name.as_str()).collect();
    let formulas: Vec<String> = (0..id.base.columns.len())
        .map(|b| id.base.formula_named(b, &names))
        .collect();
    let (standard_doc, base_doc) = docs(&names, &formulas);
    let all: Vec<usize> = (0..id.parameters.len()).collect();
    identification_impl(
        arm.joints.len(),
        header,
        &names,
        &formulas,
        [
            regressor(arm, &id.parameters, &all),
            values(arm, &id, false),
            base_regressor(arm, &id),
            values(arm, &id, true),
        ],
        (&standard_doc, &base_doc),
    )
}

/// The base regressor, with its packed program (four joints per lane), which the derive emits
/// as a second body for the AVX2 copy of the dispatch. The full regressor has none: compiled
/// twice more, its packed body added 2 s to a release build of a crate deriving the Panda
/// (docs/performance.md).
fn base_regressor(arm: &SpatialArmSpec, id: &SpatialIdentification) -> Method {
    let mut method = regressor(arm, &id.parameters, &id.base.columns);
    method.packed = packed_regressor(arm, &id.parameters, &id.base.columns).map(Box::new);
    method
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
