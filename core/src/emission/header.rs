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
    /// The joints' names, base first (a spatial arm's `JOINT_NAMES`).
    pub joint_names: Vec<String>,
    /// `JOINT_NAMES`' documentation.
    pub joint_names_doc: String,
    /// A spatial arm's `#[arm(exact_dynamics)]`: M and c multiplied out for `EXACT` whatever
    /// their size, not only within the budget that keeps builds quick.
    pub exact_dynamics: bool,
}

impl Header {
    /// The header of a type whose joints are named after its link fields.
    #[must_use]
    pub fn new(
        impl_generics: TokenStream,
        ty: TokenStream,
        where_clause: TokenStream,
        fields: Vec<proc_macro2::Ident>,
    ) -> Self {
        Self {
            joint_names: fields.iter().map(ToString::to_string).collect(),
            joint_names_doc: "The joints' names, base first: the order of `q`.".to_string(),
            impl_generics,
            ty,
            where_clause,
            fields,
            exact_dynamics: false,
        }
    }
}
