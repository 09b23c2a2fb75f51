//! The paper's closed forms, emitted for two- and three-link arms: inverse kinematics (both
//! branches, within the joints' ranges) and inverse statics, as impls of the `kinematics`
//! traits that call the run-time solvers with the arm's constant lengths inlined. Arms with a
//! prismatic joint get the polar (RP), slider-link (PR) and slider-two-link (PRR) solvers and
//! their statics by the generated Jacobian; arms with offsets or reversed joints get the
//! statics by the Jacobian and no closed-form inverse kinematics (the paper's solutions are
//! written for plain joints).

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::header::Header;
use crate::emit::{coefficient_tokens, f64_tokens, local};
use crate::mechanics::JointKind;
use crate::methods::Derived;
use crate::paths::F64;
use crate::slp::Emit;

/// Closed-form inverse kinematics and inverse statics for two and three links (the paper's
/// solutions, specialised by inlining the arm's constant lengths); nothing for other `N`.
#[must_use]
pub fn closed_forms<C: Emit>(d: &Derived<C>, header: &Header) -> TokenStream {
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    let lengths: Vec<TokenStream> = d
        .arm
        .links
        .iter()
        .map(|l| coefficient_tokens(&l.length).unwrap_or_else(|_| quote!(0.0)))
        .collect();
    let target = local("target");
    let (q, tau) = (local("q"), local("tau"));
    if !d.arm.all_revolute() || !d.arm.plain() {
        return mixed_closed_forms(d, header);
    }
    let ranged = d.arm.links.iter().any(|l| l.range.is_some());
    let ranges = range_tokens(d);
    match lengths.as_slice() {
        [l1, l2] => {
            let equal = d.arm.links[0].length == d.arm.links[1].length;
            let ik = if ranged {
                quote!(::planar_arm::kinematics::ik2_in_ranges(#l1, #l2, [#(#ranges),*], #target))
            } else if equal {
                quote!(::planar_arm::kinematics::ik2_equal(#l1, #target))
            } else {
                quote!(::planar_arm::kinematics::ik2(#l1, #l2, #target))
            };
            let doc = if equal {
                "The paper's closed form for two equal links: cos(q2/2) = r / 2l, q1 + q2/2 = atan2(y, x)."
            } else {
                "The paper's closed form: cos q2 by the law of cosines, q1 from the rotated equations."
            };
            quote! {
                #[automatically_derived]
                #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
                impl #impl_generics ::planar_arm::kinematics::ClosedFormIk<2> for #ty #where_clause {
                    type Target = ::planar_arm::nalgebra::Point2<#F64>;
                    #[doc = #doc]
                    #[inline]
                    fn inverse_kinematics(&self, #target: &::planar_arm::nalgebra::Point2<#F64>)
                        -> ::core::result::Result<[::planar_arm::nalgebra::SVector<#F64, 2>; 2], ::planar_arm::ArmError> {
                        #ik
                    }
                }
                #[automatically_derived]
                #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
                impl #impl_generics ::planar_arm::kinematics::TipForce for #ty #where_clause {
                    #[inline]
                    fn tip_force(&self, #q: &::planar_arm::nalgebra::SVector<#F64, 2>, #tau: &::planar_arm::nalgebra::SVector<#F64, 2>)
                        -> ::core::result::Result<::planar_arm::nalgebra::Vector2<#F64>, ::planar_arm::ArmError> {
                        ::planar_arm::kinematics::tip_force2(#l1, #l2, #q, #tau)
                    }
                }
            }
        }
        [l1, l2, l3] => {
            let ik3 = if ranged {
                quote!(::planar_arm::kinematics::ik3_in_ranges(#l1, #l2, #l3, [#(#ranges),*], #target))
            } else {
                quote!(::planar_arm::kinematics::ik3(#l1, #l2, #l3, #target))
            };
            quote! {
            #[automatically_derived]
            #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
            impl #impl_generics ::planar_arm::kinematics::ClosedFormIk<3> for #ty #where_clause {
                type Target = ::planar_arm::nalgebra::Isometry2<#F64>;
                /// Through the wrist point, as in the paper: the two-link solution for
                /// (x - l3 cos phi, y - l3 sin phi), then q3 = phi - q1 - q2.
                #[inline]
                fn inverse_kinematics(&self, #target: &::planar_arm::nalgebra::Isometry2<#F64>)
                    -> ::core::result::Result<[::planar_arm::nalgebra::SVector<#F64, 3>; 2], ::planar_arm::ArmError> {
                    #ik3
                }
            }
            #[automatically_derived]
            #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
            impl #impl_generics ::planar_arm::kinematics::TipWrench for #ty #where_clause {
                #[inline]
                fn tip_wrench(&self, #q: &::planar_arm::nalgebra::SVector<#F64, 3>, #tau: &::planar_arm::nalgebra::SVector<#F64, 3>)
                    -> ::core::result::Result<::planar_arm::kinematics::StaticWrench<3>, ::planar_arm::ArmError> {
                    ::planar_arm::kinematics::tip_wrench3(#l1, #l2, #l3, #q, #tau)
                }
            }
            }
        }
        _ => TokenStream::new(),
    }
}

/// Each joint's range as `Option<(f64, f64)>` tokens.
fn range_tokens<C>(d: &Derived<C>) -> Vec<TokenStream> {
    d.arm
        .links
        .iter()
        .map(|l| match &l.range {
            Some((lo, hi)) => match (f64_tokens(lo), f64_tokens(hi)) {
                (Ok(lo), Ok(hi)) => quote!(::core::option::Option::Some((#lo, #hi))),
                _ => quote!(::core::option::Option::None),
            },
            None => quote!(::core::option::Option::None),
        })
        .collect()
}

/// The `ClosedFormIk` impl whose body is `solve`, for `n` joints and the target type.
fn ik_impl(header: &Header, n: usize, doc: &str, solve: &TokenStream) -> TokenStream {
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    let target = local("target");
    let nn = Literal::usize_unsuffixed(n);
    let target_ty = if n == 2 {
        quote!(::planar_arm::nalgebra::Point2<#F64>)
    } else {
        quote!(::planar_arm::nalgebra::Isometry2<#F64>)
    };
    quote! {
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
        impl #impl_generics ::planar_arm::kinematics::ClosedFormIk<#nn> for #ty #where_clause {
            type Target = #target_ty;
            #[doc = #doc]
            #[inline]
            fn inverse_kinematics(&self, #target: &#target_ty)
                -> ::core::result::Result<[::planar_arm::nalgebra::SVector<#F64, #nn>; 2], ::planar_arm::ArmError> {
                #solve
            }
        }
    }
}

/// [`closed_forms`] of a two- or three-link arm with a prismatic joint: the closed-form inverse
/// kinematics of the polar arm (RP), a slider carrying a link (PR) and a slider carrying two
/// (PRR, for a pose), within the joints' ranges; the statics by the generated Jacobian
/// (`J^T w = tau`).
fn mixed_closed_forms<C: Emit>(d: &Derived<C>, header: &Header) -> TokenStream {
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    let (q, tau) = (local("q"), local("tau"));
    let target = local("target");
    let lengths: Vec<TokenStream> = d
        .arm
        .links
        .iter()
        .map(|l| coefficient_tokens(&l.length).unwrap_or_else(|_| quote!(0.0)))
        .collect();
    let ranges = range_tokens(d);
    let kinds: Vec<JointKind> = d.arm.links.iter().map(|l| l.joint).collect();
    let ik = match (kinds.as_slice(), lengths.as_slice(), ranges.as_slice()) {
        _ if !d.arm.plain() => TokenStream::new(),
        ([JointKind::Revolute, JointKind::Prismatic], [l1, l2], [r1, r2]) => ik_impl(
            header,
            2,
            "The polar arm: q1 = atan2(y, x) and the slide r - l1 - l2, or the opposite direction with the slide -r - l1 - l2; the branches within the ranges (see `kinematics::ik_rp`).",
            &quote!(::planar_arm::kinematics::ik_rp(#l1, #l2, #r1, #r2, #target)),
        ),
        ([JointKind::Prismatic, JointKind::Revolute], [l1, l2], [r1, r2]) => ik_impl(
            header,
            2,
            "A slider carrying a link: the link's circle about the carriage meets the target's height twice; the branches within the ranges (see `kinematics::ik_pr`).",
            &quote!(::planar_arm::kinematics::ik_pr(#l1, #l2, #r1, #r2, #target)),
        ),
        (
            [JointKind::Prismatic, JointKind::Revolute, JointKind::Revolute],
            [l1, l2, l3],
            [r1, r2, r3],
        ) => ik_impl(
            header,
            3,
            "A slider carrying two links, for a pose: the wrist point, sin q2 from its height, two branches of cos q2, the slide from its abscissa; within the ranges (see `kinematics::ik_prr`).",
            &quote!(::planar_arm::kinematics::ik_prr(#l1, #l2, #l3, [#r1, #r2, #r3], #target)),
        ),
        _ => TokenStream::new(),
    };
    let solve = |f: TokenStream| quote!(::planar_arm::__private::#f(&::planar_arm::PlanarArm::jacobian(self, #q), #q, #tau));
    let (force, wrench) = (
        solve(quote!(tip_force_by_jacobian)),
        solve(quote!(tip_wrench_by_jacobian)),
    );
    let statics = match d.arm.links.len() {
        2 => quote! {
            #[automatically_derived]
            #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
            impl #impl_generics ::planar_arm::kinematics::TipForce for #ty #where_clause {
                /// By the generated Jacobian: `J^T F = tau`, a prismatic joint's entry of
                /// `tau` a force along it.
                #[inline]
                fn tip_force(&self, #q: &::planar_arm::nalgebra::SVector<#F64, 2>, #tau: &::planar_arm::nalgebra::SVector<#F64, 2>)
                    -> ::core::result::Result<::planar_arm::nalgebra::Vector2<#F64>, ::planar_arm::ArmError> {
                    #force.map(|w| ::planar_arm::nalgebra::Vector2::new(w[0], w[1]))
                }
            }
        },
        3 => quote! {
            #[automatically_derived]
            #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
            impl #impl_generics ::planar_arm::kinematics::TipWrench for #ty #where_clause {
                /// By the generated Jacobian: `J^T (F, T) = tau`, a prismatic joint's entry of
                /// `tau` a force along it.
                #[inline]
                fn tip_wrench(&self, #q: &::planar_arm::nalgebra::SVector<#F64, 3>, #tau: &::planar_arm::nalgebra::SVector<#F64, 3>)
                    -> ::core::result::Result<::planar_arm::kinematics::StaticWrench<3>, ::planar_arm::ArmError> {
                    #wrench.map(|w| ::planar_arm::kinematics::StaticWrench {
                        force: ::planar_arm::nalgebra::Vector2::new(w[0], w[1]),
                        torque: w[2],
                        residual: ::planar_arm::nalgebra::SVector::<#F64, 3>::zeros(),
                    })
                }
            }
        },
        _ => TokenStream::new(),
    };
    quote!(#ik #statics)
}
