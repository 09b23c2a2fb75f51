//! Expansion: a valid arm goes to the engine; an invalid one gets its errors and a stub impl.

use proc_macro2::TokenStream;
use quote::{quote, ToTokens};
use syn::DeriveInput;

use planar_arm_core::emit::Derived;
use planar_arm_core::generate::{generate, Header};

use crate::ast::Arm;
use crate::check::check;
use crate::ctxt::Ctxt;

pub fn derive(input: &DeriveInput) -> TokenStream {
    match try_derive(input) {
        Ok(tokens) => tokens,
        Err(errors) => {
            let fallback = fallback(input);
            quote!(#errors #fallback)
        }
    }
}

fn try_derive(input: &DeriveInput) -> Result<TokenStream, TokenStream> {
    let cx = Ctxt::new();
    let spec = Arm::from_ast(&cx, input).and_then(|arm| check(&cx, &arm));
    cx.check()?;
    let Some(spec) = spec else {
        return Err(syn::Error::new_spanned(&input.ident, "invalid arm").to_compile_error());
    };
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let ident = &input.ident;
    let header = Header {
        impl_generics: impl_generics.to_token_stream(),
        ty: quote!(#ident #ty_generics),
        where_clause: where_clause.to_token_stream(),
        fields: field_names(input),
    };
    let derived = Derived::new(&spec);
    let mut tokens = generate(&derived, &header)
        .map_err(|e| syn::Error::new_spanned(ident, e.message).to_compile_error())?;
    tokens.extend(extras(&derived, &header));
    Ok(tokens)
}

/// Closed-form inverse kinematics and inverse statics, for the arms the paper solves.
fn extras(d: &Derived, header: &Header) -> TokenStream {
    planar_arm_core::generate::closed_forms(d, header)
}

/// After an error, a stub impl, so uses of the trait do not add a cascade of errors.
fn fallback(input: &DeriveInput) -> TokenStream {
    let Some(n) = Arm::field_count(input) else {
        return TokenStream::new();
    };
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let ident = &input.ident;
    planar_arm_core::generate::stub(
        n,
        &Header {
            impl_generics: impl_generics.to_token_stream(),
            ty: quote!(#ident #ty_generics),
            where_clause: where_clause.to_token_stream(),
            fields: field_names(input),
        },
    )
}

fn field_names(input: &DeriveInput) -> Vec<proc_macro2::Ident> {
    match &input.data {
        syn::Data::Struct(s) => s.fields.iter().filter_map(|f| f.ident.clone()).collect(),
        _ => Vec::new(),
    }
}
