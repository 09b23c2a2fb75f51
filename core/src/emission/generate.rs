//! The `impl PlanarArm<N>` that `#[derive(PlanarArm)]` emits. Its methods are data: a table
//! that one function per family of methods fills (`dynamics`, `energies`, `kinematics`,
//! `derivatives`), rendered in order, followed by the hot methods' variants that read a frozen
//! block of parameter-only values (`frozen`); next to them, the exact `const` data and the
//! arm's values (`exact`). The methods' programs come from [`crate::methods`]; each is written
//! as Rust by [`crate::emit`].

use std::fmt::Write as _;

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use super::function::{Fn, Param};
use crate::emit::{check_representable, EmitError};
use crate::methods::Derived;
use crate::paths::{F64, STR};
use crate::slp::{Emit, Input};

pub use super::header::Header;
#[doc(no_inline)]
pub use crate::closed_forms::closed_forms;

mod derivatives;
mod dynamics;
mod energies;
mod exact;
pub(crate) mod frozen;
mod kinematics;

/// What the signatures of every family's methods share.
struct Context {
    /// The number of joints.
    n: usize,
    /// `N`, the number of joints, as a literal.
    nn: Literal,
    q: Param,
    qd: Param,
    qdd: Param,
    tau: Param,
    /// `SVector<__T, N>`.
    svec: TokenStream,
    /// `SMatrix<__T, N, N>`.
    smat: TokenStream,
    /// Reads the link fields once: they are markers the generated code never reads otherwise,
    /// and the user would get `dead_code` warnings.
    touch: TokenStream,
}

impl Context {
    fn new(n: usize, header: &Header) -> Self {
        let nn = Literal::usize_unsuffixed(n);
        let fields = &header.fields;
        Self {
            n,
            q: Param::Joints("q", Input::Q),
            qd: Param::Joints("qd", Input::Qd),
            qdd: Param::Joints("qdd", Input::Qdd),
            tau: Param::Joints("tau", Input::Tau),
            svec: quote!(::planar_arm::nalgebra::SVector<__T, #nn>),
            smat: quote!(::planar_arm::nalgebra::SMatrix<__T, #nn, #nn>),
            touch: if fields.is_empty() {
                TokenStream::new()
            } else {
                quote!(let _ = (#(&self.#fields),*);)
            },
            nn,
        }
    }
}

/// A method whose body calls other generated methods and the run-time crate instead of
/// evaluating a program of its own.
struct Call<'a> {
    /// Whether it calls a hot method: then it has a variant that reads the frozen block.
    hot: bool,
    /// Its tokens, or with `Some(slots)` its variant's for a block of that many values.
    render: Box<dyn std::ops::Fn(Option<usize>) -> Result<TokenStream, EmitError> + 'a>,
}

/// The methods of the impl.
#[derive(Default)]
struct Table<'a> {
    /// The methods whose body is their program, in the impl's order.
    programs: Vec<Fn<'a>>,
    /// The methods written as calls, after the programs: those of plain methods in order, then
    /// those of hot ones, each with its frozen variant, next to the other frozen variants.
    calls: Vec<Call<'a>>,
}

impl Table<'_> {
    /// Every method's tokens, with the frozen variants and `__freeze` last.
    fn render(&self, n: usize) -> Result<Vec<TokenStream>, EmitError> {
        let hot = frozen::hot(&self.programs);
        let split = frozen::split(&hot);
        let mut items = Vec::new();
        for f in &self.programs {
            items.push(frozen::plain(n, f, &hot, split.as_ref())?);
        }
        let slots = split.as_ref().map(|fz| fz.block.outputs.len());
        for call in self.calls.iter().filter(|c| !c.hot) {
            items.push((call.render)(None)?);
        }
        for call in self.calls.iter().filter(|c| c.hot) {
            items.push((call.render)(None)?);
            if slots.is_some() {
                items.push((call.render)(slots)?);
            }
        }
        items.extend(frozen::variants(n, &hot, split.as_ref())?);
        Ok(items)
    }
}

/// The complete `impl ::planar_arm::PlanarArm<N>` for the arm.
///
/// # Errors
/// If a derived constant does not fit in `f64` or in the `i128` of the exact `const` data.
pub fn generate<C: Emit>(d: &Derived<C>, header: &Header) -> Result<TokenStream, EmitError> {
    check_representable(d)?;
    let cx = Context::new(d.arm.links.len(), header);
    let mut table = Table::default();
    dynamics::methods(d, &cx, &mut table);
    energies::methods(d, &cx, &mut table);
    kinematics::methods(d, &cx, &mut table);
    derivatives::methods(d, &cx, &mut table);
    let methods = table.render(cx.n)?;
    let model = exact::model(d)?;
    let exact = exact::derivation(d)?;
    let Header {
        impl_generics,
        ty,
        where_clause,
        joint_names,
        joint_names_doc,
        ..
    } = header;
    let nn = &cx.nn;
    let (dynamics, methods) = super::traits::split_dynamics(methods);
    Ok(quote! {
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
        impl #impl_generics ::planar_arm::Dynamics<#nn> for #ty #where_clause {
            #(#dynamics)*
        }
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)]
        impl #impl_generics ::planar_arm::PlanarArm<#nn> for #ty #where_clause {
            #exact
            #[doc = #joint_names_doc]
            const JOINT_NAMES: [&'static #STR; #nn] = [#(#joint_names),*];
            #[inline]
            fn model(&self) -> ::planar_arm::Model<#nn> {
                #model
            }
            #(#methods)*
        }
    })
}

/// A readable summary of the derivation for docs: link table and Lagrangian.
#[must_use]
pub fn summary<C: Emit>(d: &Derived<C>) -> String {
    let mut s = String::new();
    for (i, l) in d.arm.links.iter().enumerate() {
        let _ = writeln!(
            s,
            "link {}: length {}, mass {}, inertia {}, com ({}, {}), armature {}, damping {}, frictionloss {}",
            i + 1,
            l.length,
            l.mass,
            l.inertia,
            l.com.0,
            l.com.1,
            l.armature,
            l.damping,
            l.frictionloss
        );
        if let Some(o) = &l.offset {
            let _ = writeln!(s, "  offset {}", o.angle);
        }
        if l.reversed {
            let _ = writeln!(s, "  reversed");
        }
        if !l.stiffness.is_zero() {
            let _ = writeln!(s, "  spring {} toward {}", l.stiffness, l.springref);
        }
    }
    let _ = writeln!(s, "gravity {} {}", d.arm.gravity.0, d.arm.gravity.1);
    s
}

/// Stub `impl Dynamics<n>` and `impl PlanarArm<n>` whose methods are unreachable: emitted next to a compile error
/// so that uses of the trait elsewhere do not add a cascade of errors.
#[must_use]
pub fn stub(n: usize, header: &Header) -> TokenStream {
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    let nn = Literal::usize_unsuffixed(n);
    let v = quote!(&::planar_arm::nalgebra::SVector<#F64, #nn>);
    let sv = quote!(::planar_arm::nalgebra::SVector<#F64, #nn>);
    let body = quote!({ ::core::unreachable!() });
    let g = quote!(<__T: ::planar_arm::Real>);
    let vt = quote!(&::planar_arm::nalgebra::SVector<__T, #nn>);
    let mt = quote!(::planar_arm::nalgebra::SMatrix<__T, #nn, #nn>);
    let svt = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    quote! {
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
        impl #impl_generics ::planar_arm::Dynamics<#nn> for #ty #where_clause {
            fn mass_matrix #g(&self, _: #vt) -> #mt #body
            fn coriolis #g(&self, _: #vt, _: #vt) -> #svt #body
            fn coriolis_matrix #g(&self, _: #vt, _: #vt) -> #mt #body
            fn gravity #g(&self, _: #vt) -> #svt #body
            fn friction #g(&self, _: #vt) -> #svt #body
            fn bias #g(&self, _: #vt, _: #vt) -> #svt #body
            fn mass_matrix_and_bias #g(&self, _: #vt, _: #vt) -> (#mt, #svt) #body
            fn inverse_dynamics #g(&self, _: #vt, _: #vt, _: #vt) -> #svt #body
            fn forward_dynamics #g(&self, _: #vt, _: #vt, _: #vt) -> #svt #body
            fn kinetic_energy #g(&self, _: #vt, _: #vt) -> __T #body
            fn potential_energy #g(&self, _: #vt) -> __T #body
            type __Frozen = ::planar_arm::__private::Block<0>;
        }
        #[automatically_derived]
        impl #impl_generics ::planar_arm::PlanarArm<#nn> for #ty #where_clause {
            const EXACT: ::planar_arm::exact::Derivation<#nn> = ::planar_arm::exact::Derivation {
                kinetic_energy: ::planar_arm::__private::terms(b"", &[]),
                potential_energy: ::planar_arm::__private::terms(b"", &[]),
                mass_matrix: [[::planar_arm::__private::terms(b"", &[]); #nn]; #nn],
                coriolis: [::planar_arm::__private::terms(b"", &[]); #nn],
                gravity: [::planar_arm::__private::terms(b"", &[]); #nn],
            };
            const JOINT_NAMES: [&'static #STR; #nn] = [""; #nn];
            fn model(&self) -> ::planar_arm::Model<#nn> #body
            fn tip_pose(&self, _: #v) -> ::planar_arm::nalgebra::Isometry2<#F64> #body
            fn jacobian #g(&self, _: #vt) -> ::planar_arm::nalgebra::SMatrix<__T, 3, #nn> #body
            fn joint_positions #g(&self, _: #vt) -> [::planar_arm::nalgebra::Point2<__T>; #nn] #body
            fn tip_polar(&self, _: #v) -> (f64, f64) #body
            fn joint_torques(&self, _: #v, _: &::planar_arm::nalgebra::Vector2<#F64>, _: f64) -> #sv #body
        }
    }
}
