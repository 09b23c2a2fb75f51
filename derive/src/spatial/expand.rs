//! Expansion of `#[derive(SpatialArm)]`: a valid arm goes to the engine; an invalid one gets
//! its errors and a stub impl, so that uses of the trait elsewhere add no cascade.

use proc_macro2::TokenStream;
use quote::{quote, ToTokens};
use syn::DeriveInput;

use planar_arm_core::generate::Header;
use planar_arm_core::paths::F64;

use super::ast::SpatialArm;
use super::check::{check, Checked};
use crate::ctxt::Ctxt;

pub fn derive(input: &DeriveInput) -> TokenStream {
    let tokens = match try_derive(input) {
        Ok(tokens) => tokens,
        Err(errors) => {
            let stub = stub(input);
            quote!(#errors #stub)
        }
    };
    match crate::expand::krate(input) {
        Some(path) => planar_arm_core::paths::qualify(tokens, Some(&path)),
        None => tokens,
    }
}

fn try_derive(input: &DeriveInput) -> Result<TokenStream, TokenStream> {
    let cx = Ctxt::new();
    let arm = SpatialArm::from_ast(&cx, input);
    let checked = arm.as_ref().and_then(|arm| check(&cx, arm));
    cx.check()?;
    let (Some(arm), Some(Checked { spec, names, file })) = (arm, checked) else {
        return Err(syn::Error::new_spanned(&input.ident, "invalid arm").to_compile_error());
    };
    let mut header = crate::expand::header(input);
    header.joint_names.clone_from(&names);
    header.joint_names_doc = joint_names_doc(&arm, file.as_ref());
    header.exact_dynamics = arm.attrs.exact_dynamics.is_some();
    let generate = |spec: &_| planar_arm_core::spatial::generate_spatial(spec, &header);
    // As for planar arms: literals whose exact coefficients overflow `EXACT` enter as named
    // constants, fewer digits each round.
    let mut generated = generate(&spec);
    for bits in crate::expand::NAMED_BITS {
        if generated.is_ok() {
            break;
        }
        let named = spec.map_values(|p| crate::expand::named_if_long(p, bits));
        if named != spec {
            if let Ok(tokens) = generate(&named) {
                generated = Ok(tokens);
            }
        }
    }
    let mut tokens = generated.map_err(|e| {
        // The key's own refusal points at the key.
        let at = match &arm.attrs.exact_dynamics {
            Some(key) if e.message.starts_with("`exact_dynamics`") => key.clone(),
            _ => input.ident.to_token_stream(),
        };
        syn::Error::new_spanned(at, e.to_string()).to_compile_error()
    })?;
    tokens.extend(joint_types(&arm));
    if let Some(f) = &file {
        // `include_bytes!` is how a derive makes cargo rebuild the user's crate when a file it
        // read changes.
        let path = f.path.display().to_string();
        tokens.extend(quote!(
            const _: &[u8] = ::core::include_bytes!(#path);
        ));
    }
    tokens.extend(crate::expand::param_accessors_of(
        arm.attrs
            .params
            .iter()
            .chain(arm.joints.iter().flat_map(|j| j.attrs.params.iter()))
            .map(|p| p.name.clone())
            .collect(),
        &arm.others,
        &header,
    ));
    Ok(tokens)
}

/// The check that every joint field is `planar_arm::Revolute` or `Prismatic`.
fn joint_types(arm: &SpatialArm<'_>) -> TokenStream {
    let checks = arm.joints.iter().map(|j| {
        let ty = &j.field.ty;
        let check = match j.kind {
            planar_arm_core::JointKind::Revolute => quote!(link_field),
            planar_arm_core::JointKind::Prismatic => quote!(prismatic_field),
        };
        quote::quote_spanned!(syn::spanned::Spanned::span(ty)=> ::planar_arm::__private::#check::<#ty>();)
    });
    quote!(const _: () = { #(#checks)* };)
}

/// `JOINT_NAMES`' documentation: for an arm read from a file, the file and what the reading
/// locked or ignored.
fn joint_names_doc(arm: &SpatialArm<'_>, file: Option<&crate::models::Imported>) -> String {
    let (Some(f), Some((_, lit))) = (file, &arm.attrs.model) else {
        return "The joints' names, base first: the order of `q`.".to_string();
    };
    let mut doc = vec![format!(
        "The joints' names in `{}`, base first: the order of `q`.",
        lit.value()
    )];
    doc.extend(f.notes.iter().cloned());
    doc.join("\n\n")
}

/// A stub impl whose methods are unreachable, emitted next to a compile error.
fn stub(input: &DeriveInput) -> TokenStream {
    if input.generics.type_params().any(|p| p.ident == "__T") {
        return TokenStream::new();
    }
    let n = match &input.data {
        syn::Data::Struct(s) => s
            .fields
            .iter()
            .filter(|f| crate::ast::joint_kind(&f.ty).is_some())
            .count(),
        _ => 0,
    };
    if n == 0 {
        return TokenStream::new();
    }
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = crate::expand::header(input);
    let nn = proc_macro2::Literal::usize_unsuffixed(n);
    let v = quote!(&::planar_arm::nalgebra::SVector<#F64, #nn>);
    let vt = quote!(&::planar_arm::nalgebra::SVector<__T, #nn>);
    let body = quote!({ ::core::unreachable!() });
    let _ = ToTokens::to_token_stream(&input.ident);
    quote! {
        #[automatically_derived]
        impl #impl_generics ::planar_arm::Dynamics<#nn> for #ty #where_clause {
            fn gravity<__T: ::planar_arm::Real>(&self, _: #vt) -> ::planar_arm::nalgebra::SVector<__T, #nn> #body
            fn potential_energy<__T: ::planar_arm::Real>(&self, _: #vt) -> __T #body
            fn inverse_dynamics<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt, _: #vt) -> ::planar_arm::nalgebra::SVector<__T, #nn> #body
            fn forward_dynamics<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt, _: #vt) -> ::planar_arm::nalgebra::SVector<__T, #nn> #body
            fn kinetic_energy<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt) -> __T #body
            fn mass_matrix<__T: ::planar_arm::Real>(&self, _: #vt) -> ::planar_arm::nalgebra::SMatrix<__T, #nn, #nn> #body
            fn coriolis<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt) -> ::planar_arm::nalgebra::SVector<__T, #nn> #body
            fn coriolis_matrix<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt) -> ::planar_arm::nalgebra::SMatrix<__T, #nn, #nn> #body
            fn friction<__T: ::planar_arm::Real>(&self, _: #vt) -> ::planar_arm::nalgebra::SVector<__T, #nn> #body
            fn bias<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt) -> ::planar_arm::nalgebra::SVector<__T, #nn> #body
            fn mass_matrix_and_bias<__T: ::planar_arm::Real>(&self, _: #vt, _: #vt)
                -> (::planar_arm::nalgebra::SMatrix<__T, #nn, #nn>, ::planar_arm::nalgebra::SVector<__T, #nn>) #body
            type __Frozen = ::planar_arm::__private::Block<0>;
        }
        #[automatically_derived]
        impl #impl_generics ::planar_arm::spatial::SpatialArm<#nn> for #ty #where_clause {
            const EXACT: ::planar_arm::exact::SpatialDerivation<#nn> = ::planar_arm::exact::SpatialDerivation {
                expansion: ::core::option::Option::None,
            };
            const JOINT_NAMES: [&'static str; #nn] = [""; #nn];
            fn tip_pose(&self, _: #v) -> ::planar_arm::nalgebra::Isometry3<#F64> #body
            fn link_poses(&self, _: #v) -> [::planar_arm::nalgebra::Isometry3<#F64>; #nn] #body
            fn jacobian<__T: ::planar_arm::Real>(&self, _: #vt) -> ::planar_arm::nalgebra::SMatrix<__T, 6, #nn> #body
            fn model(&self) -> ::planar_arm::spatial::SpatialModel<#nn> #body
            fn inverse_kinematics(&self, _: &::planar_arm::nalgebra::Isometry3<#F64>)
                -> ::core::result::Result<::planar_arm::spatial::IkSolutions<#nn>, ::planar_arm::ArmError> #body
        }
    }
}
