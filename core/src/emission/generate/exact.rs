//! The exact data of the impl: `EXACT`, the derivation in the compact encoding of
//! [`crate::compact`], and `model()`, the arm's values.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emit::{coefficient_tokens, f64_tokens, f64_value_tokens, local, EmitError};
use crate::expr::Expr;
use crate::mechanics::JointKind;
use crate::methods::Derived;
use crate::paths::STR;
use crate::slp::Emit;

/// `::planar_arm::__private::terms(b"...", __NAMES)`: the sum in the compact encoding of
/// [`crate::compact`], its parameters named by index into the `EXACT` block's name table.
fn exact_terms<C: Emit>(e: &Expr<C>, names: &mut Vec<String>) -> Result<TokenStream, EmitError> {
    let code = Literal::byte_string(&crate::compact::encode(e, names)?);
    let table = local("NAMES");
    Ok(quote!(::planar_arm::__private::terms(#code, #table)))
}

/// `const EXACT`: T, V, M, c and g, their parameters named by index into one table.
pub(super) fn derivation<C: Emit>(d: &Derived<C>) -> Result<TokenStream, EmitError> {
    let dy = &d.dynamics;
    let nn = Literal::usize_unsuffixed(dy.n);
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
    Ok(quote! {
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
    })
}

/// `::planar_arm::Model { ... }` with the arm's values, read from `self` where they are
/// run-time parameters.
pub(super) fn model<C: Emit>(d: &Derived<C>) -> Result<TokenStream, EmitError> {
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
            let (stiffness, springref) = (v(&l.stiffness)?, v(&l.springref)?);
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
            let offset = f64_value_tokens(l.offset.as_ref().map_or(0.0, |o| o.angle.value()))?;
            let reversed = l.reversed;
            Ok(quote!(::planar_arm::Link {
                length: #length, mass: #mass, inertia: #inertia, com: #com,
                armature: #armature, damping: #damping, frictionloss: #frictionloss,
                joint: #joint, range: #range, offset: #offset, reversed: #reversed,
                stiffness: #stiffness, springref: #springref,
            }))
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let gravity = vec2(&d.arm.gravity)?;
    let payload = match &d.arm.payload {
        None => quote!(::planar_arm::Payload::NONE),
        Some(p) => {
            let (mass, inertia, com) = (v(&p.mass)?, v(&p.inertia)?, vec2(&p.com)?);
            quote!(::planar_arm::Payload { mass: #mass, inertia: #inertia, com: #com })
        }
    };
    Ok(quote!(::planar_arm::Model { links: [#(#links),*], gravity: #gravity, payload: #payload }))
}
