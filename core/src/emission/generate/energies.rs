//! The energies' methods: T, as its formula or as `qd^T M qd / 2` on `mass_matrix`, and V.

use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;

use super::{Call, Context, Table};
use crate::emission::function::Fn;
use crate::emit::{formula_doc, local};
use crate::methods::{Derived, Method};
use crate::slp::Emit;

/// Pushes the energies' methods.
pub(super) fn methods<'a, C: Emit>(d: &'a Derived<C>, cx: &Context, table: &mut Table<'a>) {
    let dy = &d.dynamics;
    let doc = formula_doc("The kinetic energy.", &[("T".into(), &dy.kinetic_energy)]);
    let (method, quadratic) = d.kinetic_energy_choice();
    if quadratic {
        let tokens = quadratic_kinetic_energy(cx.n, &doc, &method);
        table.calls.push(Call {
            hot: false,
            render: Box::new(move |_| Ok(tokens.clone())),
        });
    } else {
        table.programs.push(Fn::new(
            "kinetic_energy",
            vec![cx.q, cx.qd],
            quote!(__T),
            doc,
            method,
            Box::new(scalar),
        ));
    }
    table.programs.push(Fn::new(
        "potential_energy",
        vec![cx.q],
        quote!(__T),
        formula_doc(
            "The potential energy (zero at y = 0).",
            &[("V".into(), &dy.potential_energy)],
        ),
        d.potential_energy_method(),
        Box::new(scalar),
    ));
}

/// The one output as the return value.
fn scalar(ids: &[Ident]) -> TokenStream {
    let i = &ids[0];
    quote!(#i)
}

/// `kinetic_energy` as `qd^T M qd / 2` with `M` from `mass_matrix`, which the run-time crate's
/// product then costs nothing to type-check again in the user's crate:
/// `planar_arm::__private::kinetic_energy` performs the operations that `quadratic` (the
/// quadratic form on the mass matrix's program) appends to M's, so the cost printed is that
/// program's.
fn quadratic_kinetic_energy(n: usize, doc: &str, quadratic: &Method) -> TokenStream {
    let nn = Literal::usize_unsuffixed(n);
    let v = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    let (q, qd) = (local("q"), local("qd"));
    let doc = format!(
        "{doc}\n\nEvaluated as `qd^T M qd / 2` with M from `mass_matrix` (cheaper than the \
         formula for this arm).\n\nCost: {}.",
        quadratic.op_count()
    );
    quote! {
        #[doc = #doc]
        #[inline]
        fn kinetic_energy<__T: ::planar_arm::Real>(&self, #q: &#v, #qd: &#v) -> __T {
            ::planar_arm::__private::kinetic_energy(&self.mass_matrix(#q), #qd)
        }
    }
}
