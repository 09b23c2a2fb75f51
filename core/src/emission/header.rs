//! What the emitted impls need of the user's type.

use proc_macro2::TokenStream;

/// The pieces of the user's type that the impl header needs.
pub struct Header {
    /// `impl<...>` generics.
    pub impl_generics: TokenStream,
    /// The type, with its generics.
    pub ty: TokenStream,
    /// The where clause.
    pub where_clause: TokenStream,
    /// The link fields' names: the generated code reads them once, because the marker fields
    /// are otherwise never read and the user would get `dead_code` warnings.
    pub fields: Vec<proc_macro2::Ident>,
}
