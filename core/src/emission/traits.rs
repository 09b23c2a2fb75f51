//! Which trait each generated method belongs to: the equations of motion go in
//! `impl ::planar_arm::Dynamics<N>`, which both derives emit, the rest in the geometry's own
//! trait (`PlanarArm<N>`, `SpatialArm<N>`).

use proc_macro2::{TokenStream, TokenTree};

/// The methods of `planar_arm::Dynamics`, which a derive emits.
const DYNAMICS: &[&str] = &[
    "mass_matrix",
    "coriolis",
    "coriolis_matrix",
    "gravity",
    "friction",
    "bias",
    "mass_matrix_and_bias",
    "inverse_dynamics",
    "forward_dynamics",
    "inverse_dynamics_derivatives",
    "forward_dynamics_derivatives",
    "kinetic_energy",
    "potential_energy",
];

/// The name of the function an item declares: the identifier after `fn`, past its attributes.
fn name(item: &TokenStream) -> Option<String> {
    let mut after_fn = false;
    for token in item.clone() {
        if let TokenTree::Ident(ident) = token {
            if after_fn {
                return Some(ident.to_string());
            }
            after_fn = ident == "fn";
        }
    }
    None
}

/// `(Dynamics' methods, the others)`, each in the order given.
pub(crate) fn split_dynamics(items: Vec<TokenStream>) -> (Vec<TokenStream>, Vec<TokenStream>) {
    items
        .into_iter()
        .partition(|item| name(item).is_some_and(|n| DYNAMICS.contains(&n.as_str())))
}

#[cfg(test)]
mod tests {
    use quote::quote;

    #[test]
    fn methods_go_to_their_traits() {
        let items = vec![
            quote!(
                #[doc = "M"]
                #[inline]
                fn mass_matrix<__T: Real>(&self) {}
            ),
            quote!(
                fn tip_pose(&self) {}
            ),
            quote!(
                #[doc(hidden)]
                fn __mass_matrix_frozen(&self) {}
            ),
            quote!(
                fn forward_dynamics(&self) {}
            ),
        ];
        let (dynamics, rest) = super::split_dynamics(items);
        assert_eq!(dynamics.len(), 2);
        assert_eq!(rest.len(), 2);
        assert_eq!(
            super::name(&rest[1]).as_deref(),
            Some("__mass_matrix_frozen")
        );
    }
}
