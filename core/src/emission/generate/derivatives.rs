//! The derivatives' methods: of the inverse and the forward dynamics, when the arm is small
//! enough that their programs are worth their compile time (see [`crate::derivative`]).

use quote::quote;

use super::{Context, Table};
use crate::emission::function::{matrix, Fn};
use crate::methods::Derived;
use crate::paths::F64;
use crate::slp::Emit;

/// Pushes the derivatives' methods the arm gets.
pub(super) fn methods<'a, C: Emit>(d: &'a Derived<C>, cx: &Context, table: &mut Table<'a>) {
    let (n, nn) = (cx.n, &cx.nn);
    let f64mat = quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>);
    if let Some(method) = d.inverse_dynamics_derivatives_method() {
        table.programs.push(
            Fn::new(
                "inverse_dynamics_derivatives",
                vec![cx.q, cx.qd, cx.qdd],
                quote!((#f64mat, #f64mat)),
                "The partial derivatives of `inverse_dynamics`, `(dtau/dq, dtau/dqd)` (`dtau/dqdd` \
                 is `mass_matrix`), straight-line code differentiated exactly at compile time. \
                 Coulomb friction contributes 0 to `dtau/dqd`, also at `qd_i = 0` where it jumps."
                    .to_string(),
                method,
                Box::new(move |ids| {
                    let dq = matrix(n, n, &ids[..n * n]);
                    let dqd = matrix(n, n, &ids[n * n..]);
                    quote!((#dq, #dqd))
                }),
            )
            .in_f64()
            .dispatched("InverseDynamicsDerivatives", quote!(#nn)),
        );
    }
    if let Some(method) = d.forward_dynamics_derivatives_method() {
        table.programs.push(
            Fn::new(
                "forward_dynamics_derivatives",
                vec![cx.q, cx.qd, cx.tau],
                quote!((#f64mat, #f64mat, #f64mat)),
                "The partial derivatives of `forward_dynamics`, `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, \
                 straight-line code built at compile time. Coulomb friction as in \
                 `inverse_dynamics_derivatives`."
                    .to_string(),
                method,
                Box::new(move |ids| {
                    let m = (0..3).map(|k| matrix(n, n, &ids[k * n * n..(k + 1) * n * n]));
                    quote!((#(#m),*))
                }),
            )
            .in_f64()
            .dispatched("ForwardDynamicsDerivatives", quote!(#nn)),
        );
    }
}
