//! One generated method from its program: the signature, the inputs unpacked into locals,
//! the rendered statements and the return value.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emit::{input_name, local, render, EmitError, Scalar};
use crate::methods::Method;
use crate::paths::F64;
use crate::slp::Input;

/// A parameter of a generated method.
#[derive(Clone, Copy)]
pub(crate) enum Param {
    /// `&SVector<f64, N>` unpacked into per-joint locals.
    Joints(&'static str, fn(usize) -> Input),
    /// `&Vector2<f64>` unpacked into `u, v`.
    Force,
    /// `f64` tip torque.
    Torque,
}

/// Builds a method's return value from its output identifiers.
pub(crate) type Finish<'a> = Box<dyn std::ops::Fn(&[proc_macro2::Ident]) -> TokenStream + 'a>;

pub(crate) struct Fn<'a> {
    pub(crate) name: &'static str,
    pub(crate) params: Vec<Param>,
    pub(crate) ret: TokenStream,
    pub(crate) doc: String,
    pub(crate) method: Method,
    /// Statements before the body.
    pub(crate) touch: TokenStream,
    /// Builds the return value from the output identifiers.
    pub(crate) finish: Finish<'a>,
    /// Emitted generic over the scalar (`fn NAME<__T: ::planar_arm::Real>`), its vectors of
    /// `__T`.
    pub(crate) generic: bool,
}

/// Emits `f`, or with `frozen = Some((method, slots))` its hidden variant
/// `__NAME_frozen(&self, __block, ...)` that evaluates `method`, whose parameter-only values
/// are read from a block of `slots` values.
pub(crate) fn emit_fn(
    n: usize,
    f: &Fn<'_>,
    frozen: Option<(&Method, usize)>,
) -> Result<TokenStream, EmitError> {
    let method = frozen.map_or(&f.method, |(m, _)| m);
    let scalar = if f.generic {
        Scalar::Generic
    } else {
        Scalar::F64
    };
    let rendered = render(method, scalar)?;
    let real = if f.generic { quote!(__T) } else { quote!(#F64) };
    let nn = Literal::usize_unsuffixed(n);
    let mut params = Vec::new();
    let mut unpack = Vec::new();
    if let Some((_, slots)) = frozen {
        let (block, slots) = (local("block"), Literal::usize_unsuffixed(slots));
        params.push(quote!(#block: &::planar_arm::__private::Block<#slots>));
    }
    for p in &f.params {
        match *p {
            Param::Joints(name, kind) => {
                let used: Vec<bool> = (0..n)
                    .map(|j| rendered.inputs_used.contains(&kind(j)))
                    .collect();
                let pname = if used.iter().any(|&u| u) {
                    local(name)
                } else {
                    local("_")
                };
                params.push(quote!(#pname: &::planar_arm::nalgebra::SVector<#real, #nn>));
                if used.iter().any(|&u| u) {
                    let pats = (0..n).map(|j| {
                        if used[j] {
                            let id = local(&input_name(kind(j), &[]));
                            quote!(#id)
                        } else {
                            quote!(_)
                        }
                    });
                    unpack
                        .push(quote!(let [#(#pats),*] = ::planar_arm::__private::unpack(#pname);));
                }
            }
            Param::Force => {
                let u = rendered.inputs_used.contains(&Input::Force(0));
                let v = rendered.inputs_used.contains(&Input::Force(1));
                let pname = if u || v { local("force") } else { local("_") };
                params.push(quote!(#pname: &::planar_arm::nalgebra::Vector2<#F64>));
                if u || v {
                    let (u, v) = (local("u"), local("v"));
                    unpack.push(quote!(let [#u, #v] = ::planar_arm::__private::unpack(#pname);));
                }
            }
            Param::Torque => {
                let pname = if rendered.inputs_used.contains(&Input::TipTorque) {
                    local("torque")
                } else {
                    local("_")
                };
                params.push(quote!(#pname: #F64));
            }
        }
    }
    let touch = &f.touch;
    let statements = &rendered.statements;
    let result = (f.finish)(&rendered.outputs);
    let ret = &f.ret;
    let (name, doc, hidden) = if frozen.is_some() {
        let doc = format!(
            "`{}` with the parameter-only values read from a block computed by `__freeze`. Cost: {}.",
            f.name,
            method.op_count()
        );
        (
            quote::format_ident!("__{}_frozen", f.name),
            doc,
            quote!(#[doc(hidden)]),
        )
    } else {
        let evaluation = if method.evaluation.is_empty() {
            String::new()
        } else {
            format!("{}\n\n", method.evaluation)
        };
        let doc = format!("{}\n\n{evaluation}Cost: {}.", f.doc, method.op_count());
        (quote::format_ident!("{}", f.name), doc, TokenStream::new())
    };
    let generics = if f.generic {
        quote!(<__T: ::planar_arm::Real>)
    } else {
        TokenStream::new()
    };
    // A frozen variant that is also the body of its plain method (see `frozen_wrapper`) must
    // cost that method nothing over the code it used to hold.
    let inline = if frozen.is_some() && calls_frozen(n, f.name) {
        quote!(#[inline(always)])
    } else {
        quote!(#[inline])
    };
    Ok(quote! {
        #[doc = #doc]
        #hidden
        #inline
        fn #name #generics(&self, #(#params),*) -> #ret {
            #touch
            #(#unpack)*
            #(#statements)*
            #result
        }
    })
}

/// Whether the plain hot method `name` of an arm of `n` joints with run-time parameters is
/// emitted as a call of its frozen variant (`frozen_wrapper` of [`crate::generate`]). Measured, one run each,
/// interleaved, against their own bodies: 0.96-1.03x at three to six links; `mass_matrix`
/// 1.04-1.12x there, so it keeps its body; at two links `mass_matrix_and_bias` 1.06-1.09x, so
/// they all do.
pub(crate) fn calls_frozen(n: usize, name: &str) -> bool {
    n >= 3 && name != "mass_matrix"
}

pub(crate) fn matrix(rows: usize, cols: usize, ids: &[proc_macro2::Ident]) -> TokenStream {
    let rows = (0..rows).map(|r| {
        let row = &ids[r * cols..(r + 1) * cols];
        quote!([#(#row),*])
    });
    quote!(::planar_arm::__private::matrix([#(#rows),*]))
}

pub(crate) fn vector(ids: &[proc_macro2::Ident]) -> TokenStream {
    quote!(::planar_arm::__private::vector([#(#ids),*]))
}
