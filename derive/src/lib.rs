//! `#[derive(PlanarArm)]`.
use proc_macro::TokenStream;

/// Derives the arm.
#[proc_macro_derive(PlanarArm, attributes(arm))]
pub fn derive_planar_arm(_input: TokenStream) -> TokenStream {
    TokenStream::new()
}
