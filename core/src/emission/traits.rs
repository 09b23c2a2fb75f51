//! Which trait each generated method belongs to: the equations of motion and their frozen
//! variants go in `impl ::planar_arm::Dynamics<N>`, which both derives emit, the rest in the
//! geometry's own trait (`PlanarArm<N>`, `SpatialArm<N>`).

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
    "__mass_matrix_and_bias_body",
    "inverse_dynamics",
    "forward_dynamics",
    "inverse_dynamics_derivatives",
    "__inverse_dynamics_derivatives_kernel",
    "__inverse_dynamics_derivatives_packed",
    "forward_dynamics_derivatives",
    "__forward_dynamics_derivatives_kernel",
    "__forward_dynamics_derivatives_packed",
    "__forward_dynamics_derivatives_adjoint",
    "kinetic_energy",
    "potential_energy",
    "__Frozen",
    "__freeze",
    "__mass_matrix_frozen",
    "__bias_frozen",
    "__mass_matrix_and_bias_frozen",
    "__inverse_dynamics_frozen",
    "__forward_dynamics_frozen",
];

/// The name of the function or type an item declares: the identifier after `fn` or `type`,
/// past its attributes.
fn name(item: &TokenStream) -> Option<String> {
    let mut after_keyword = false;
    for token in item.clone() {
        if let TokenTree::Ident(ident) = token {
            if after_keyword {
                return Some(ident.to_string());
            }
            after_keyword = ident == "fn" || ident == "type";
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
            quote!(
                #[doc(hidden)]
                type __Frozen = Block<3>;
            ),
            quote!(
                const EXACT: u8 = 0;
            ),
        ];
        let (dynamics, rest) = super::split_dynamics(items);
        let names: Vec<_> = dynamics.iter().filter_map(super::name).collect();
        assert_eq!(
            names,
            [
                "mass_matrix",
                "__mass_matrix_frozen",
                "forward_dynamics",
                "__Frozen"
            ]
        );
        assert_eq!(rest.len(), 2);
        assert_eq!(super::name(&rest[0]).as_deref(), Some("tip_pose"));
    }
}
