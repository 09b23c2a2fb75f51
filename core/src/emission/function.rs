//! One generated method from its program: the signature, the inputs unpacked into locals,
//! the rendered statements and the return value.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emit::{input_name, local, render, EmitError, Rendered, Scalar};
use crate::methods::Method;
use crate::packed::Packed;
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

/// A generated method whose body is its program.
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
    /// Run through `::planar_arm::__private::dispatch` (see `src/dispatch.rs`): the kernel's
    /// type there and its const arguments after `Self`. The body goes in a hidden
    /// `__NAME_kernel`, which the method hands to the kernel with its inputs.
    pub(crate) kernel: Option<(&'static str, TokenStream)>,
    /// The body goes in a hidden `#[inline(always)]` `__NAME_body`, which the method calls, so
    /// that a caller compiled for other target features (the AVX2 copy of the forward
    /// dynamics' derivatives) gets the body compiled into it rather than a call of the
    /// baseline one.
    pub(crate) inlined_body: bool,
}

impl<'a> Fn<'a> {
    /// A method generic over the scalar, with nothing before its body.
    pub(crate) fn new(
        name: &'static str,
        params: Vec<Param>,
        ret: TokenStream,
        doc: String,
        method: Method,
        finish: Finish<'a>,
    ) -> Self {
        Self {
            name,
            params,
            ret,
            doc,
            method,
            touch: TokenStream::new(),
            finish,
            generic: true,
            kernel: None,
            inlined_body: false,
        }
    }

    /// The same method run through the kernel `name` of `::planar_arm::__private` with the
    /// const arguments `args`.
    pub(crate) fn dispatched(mut self, name: &'static str, args: TokenStream) -> Self {
        self.kernel = Some((name, args));
        self
    }

    /// The same method with its body in a hidden `__NAME_body` that callers can inline.
    pub(crate) fn with_inlined_body(mut self) -> Self {
        self.inlined_body = true;
        self
    }

    /// The name of the hidden body of a method [`with_inlined_body`](Self::with_inlined_body).
    pub(crate) fn body_name(&self) -> proc_macro2::Ident {
        quote::format_ident!("__{}_body", self.name)
    }

    /// The same method in `f64` only.
    pub(crate) fn in_f64(mut self) -> Self {
        self.generic = false;
        self
    }

    /// The same method with `touch` before its body.
    pub(crate) fn touching(mut self, touch: TokenStream) -> Self {
        self.touch = touch;
        self
    }
}

/// The hidden variant of a method that reads its parameter-only values from a frozen block
/// (see [`crate::frozen`]).
#[derive(Clone, Copy)]
pub(crate) struct FrozenVariant<'m> {
    /// The method split at its parameter-only frontier.
    pub(crate) method: &'m Method,
    /// The number of values in the block.
    pub(crate) slots: usize,
    /// Whether the plain method is a call of this variant, which must then cost it nothing
    /// over the code it used to hold.
    pub(crate) is_body: bool,
}

/// Emits `f`, or with `frozen` its hidden variant `__NAME_frozen(&self, __block, ...)`.
pub(crate) fn emit_fn(
    n: usize,
    f: &Fn<'_>,
    frozen: Option<FrozenVariant<'_>>,
) -> Result<TokenStream, EmitError> {
    let method = frozen.map_or(&f.method, |v| v.method);
    let scalar = if f.generic {
        Scalar::Generic
    } else {
        Scalar::F64
    };
    // A dispatched method with a packed program gets it as a second hidden body, which the
    // dispatch runs where its lanes are registers.
    let packed = method
        .packed
        .as_deref()
        .filter(|_| frozen.is_none() && f.kernel.is_some());
    let rendered = render(method, scalar)?;
    let (mut params, unpack) = parameters(n, f, &rendered);
    if let Some(v) = frozen {
        let (block, slots) = (local("block"), Literal::usize_unsuffixed(v.slots));
        params.insert(0, quote!(#block: &::planar_arm::__private::Block<#slots>));
    }
    let statements = &rendered.statements;
    let result = (f.finish)(&rendered.outputs);
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
        let cost = match packed {
            Some(pk) => format!(
                "{}; where the processor has AVX2 and FMA, {} on scalars and {} four-lane \
                 operations ({} of them fused multiply-adds)",
                method.op_count(),
                pk.values.op_count(),
                pk.lane_op_count(),
                pk.fused_count(),
            ),
            None => method.op_count().to_string(),
        };
        let doc = format!("{}\n\n{evaluation}Cost: {cost}.", f.doc);
        (quote::format_ident!("{}", f.name), doc, TokenStream::new())
    };
    let generics = if f.generic {
        quote!(<__T: ::planar_arm::Real>)
    } else {
        TokenStream::new()
    };
    let inline = if frozen.is_some_and(|v| v.is_body) {
        quote!(#[inline(always)])
    } else {
        quote!(#[inline])
    };
    // A dispatched method is a call of its kernel, and the body goes in the hidden
    // `__NAME_kernel` that the kernel runs.
    let (body, attrs, wrapper) = match (&f.kernel, frozen) {
        (Some((kernel, args)), None) => (
            quote::format_ident!("__{}_kernel", f.name),
            quote!(#[doc(hidden)] #[inline(always)]),
            dispatcher(
                n,
                f,
                kernel,
                args,
                quote!(#[doc = #doc] #inline fn #name #generics),
            ),
        ),
        (None, None) if f.inlined_body => (
            f.body_name(),
            quote!(#[doc(hidden)] #[inline(always)]),
            forwarder(n, f, quote!(#[doc = #doc] #inline fn #name #generics))?,
        ),
        _ => (
            name,
            quote!(#[doc = #doc] #hidden #inline),
            TokenStream::new(),
        ),
    };
    let packed = match packed {
        Some(pk) => packed_body(n, f, pk)?,
        None => TokenStream::new(),
    };
    let body = function(
        quote!(#attrs fn #body #generics),
        &params,
        f,
        (&unpack, statements),
        &result,
    );
    Ok(quote!(#wrapper #body #packed))
}

/// `head(&self, params) -> RET { touch; unpack; statements; result }`: a method body.
fn function(
    head: TokenStream,
    params: &[TokenStream],
    f: &Fn<'_>,
    (unpack, statements): (&[TokenStream], &[TokenStream]),
    result: &TokenStream,
) -> TokenStream {
    let (touch, ret) = (&f.touch, &f.ret);
    quote! {
        #head(&self, #(#params),*) -> #ret {
            #touch
            #(#unpack)*
            #(#statements)*
            #result
        }
    }
}

/// The hidden `__NAME_packed(&self, __lanes, inputs)`: `f`'s outputs from the packed program
/// `pk`, in the lanes the dispatch passes.
fn packed_body(n: usize, f: &Fn<'_>, pk: &Packed) -> Result<TokenStream, EmitError> {
    lanes_body(n, f, pk, "packed", None)
}

/// The hidden `__forward_dynamics_derivatives_adjoint(&self, __lanes, q, qd, qdd, __minv)` of
/// `f` (the inverse dynamics' derivatives' signature): `(-M^-1 dtau/dq, -M^-1 dtau/dqd)` from
/// the reverse-mode program `pk`, whose seeds read `__minv` (`programs::adjoint`).
pub(crate) fn adjoint_body(n: usize, f: &Fn<'_>, pk: &Packed) -> Result<TokenStream, EmitError> {
    let (minv, nn) = (local("minv"), Literal::usize_unsuffixed(n));
    lanes_body(
        n,
        f,
        pk,
        "adjoint",
        Some(quote!(#minv: &::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>)),
    )
}

/// The hidden `__NAME_SUFFIX(&self, __lanes, inputs, extra)`: `f`'s outputs from the lane
/// program `pk`.
fn lanes_body(
    n: usize,
    f: &Fn<'_>,
    pk: &Packed,
    suffix: &str,
    extra: Option<TokenStream>,
) -> Result<TokenStream, EmitError> {
    let rendered = super::packed::render_packed(pk)?;
    let (mut params, unpack) = parameters(n, f, &rendered);
    let lanes = local("lanes");
    params.insert(0, quote!(#lanes: __L));
    params.extend(extra);
    let result = (f.finish)(&rendered.outputs);
    let name = quote::format_ident!("__{}_{suffix}", f.name);
    let generics = if f.generic {
        quote!(<__T: ::planar_arm::Real, __L: ::planar_arm::__private::Lanes>)
    } else {
        quote!(<__L: ::planar_arm::__private::Lanes>)
    };
    Ok(function(
        quote!(#[doc(hidden)] #[inline(always)] fn #name #generics),
        &params,
        f,
        (&unpack, &rendered.statements),
        &result,
    ))
}

/// `head(&self, inputs) -> RET { self.__NAME_body(inputs) }`: the method `f` as a call of its
/// hidden body (see [`Fn::inlined_body`]).
///
/// # Errors
///
/// An internal error for a method that takes a tip load, which this does not hand on.
pub(crate) fn forwarder(n: usize, f: &Fn<'_>, head: TokenStream) -> Result<TokenStream, EmitError> {
    if f.params.iter().any(|p| !matches!(p, Param::Joints(..))) {
        return Err(EmitError {
            message: format!(
                "internal: `{}` has an inlined body but takes a tip load",
                f.name
            ),
        });
    }
    let body = f.body_name();
    let (_, locals) = joint_inputs(f);
    Ok(delegate(
        n,
        f,
        head,
        &locals,
        &quote!(self.#body(#(#locals),*)),
    ))
}

/// `head(&self, inputs) -> RET { dispatch(KERNEL::<Self, ARGS> { arm: self, inputs }) }`: the
/// method `f` handing its inputs to the kernel `kernel` of `::planar_arm::__private`.
fn dispatcher(
    n: usize,
    f: &Fn<'_>,
    kernel: &str,
    args: &TokenStream,
    head: TokenStream,
) -> TokenStream {
    let kernel = quote::format_ident!("{kernel}");
    let (fields, locals) = joint_inputs(f);
    let call = quote! {
        ::planar_arm::__private::dispatch(::planar_arm::__private::#kernel::<Self, #args> {
            arm: self,
            #(#fields: #locals),*
        })
    };
    delegate(n, f, head, &locals, &call)
}

/// The joint-vector inputs of `f`: their names, and the locals the method binds them to.
fn joint_inputs(f: &Fn<'_>) -> (Vec<proc_macro2::Ident>, Vec<proc_macro2::Ident>) {
    f.params
        .iter()
        .filter_map(|p| match *p {
            Param::Joints(name, _) => Some((quote::format_ident!("{name}"), local(name))),
            Param::Force | Param::Torque => None,
        })
        .unzip()
}

/// `head(&self, locals) -> RET { call }`: a method that hands its joint vectors on.
fn delegate(
    n: usize,
    f: &Fn<'_>,
    head: TokenStream,
    locals: &[proc_macro2::Ident],
    call: &TokenStream,
) -> TokenStream {
    let real = if f.generic { quote!(__T) } else { quote!(#F64) };
    let nn = Literal::usize_unsuffixed(n);
    let ret = &f.ret;
    quote! {
        #head(&self, #(#locals: &::planar_arm::nalgebra::SVector<#real, #nn>),*) -> #ret {
            #call
        }
    }
}

/// The parameters of `f` as the rendered body reads them, and the statements that unpack them
/// into the inputs' locals. A parameter the body does not read is `_`.
fn parameters(n: usize, f: &Fn<'_>, rendered: &Rendered) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let real = if f.generic { quote!(__T) } else { quote!(#F64) };
    let nn = Literal::usize_unsuffixed(n);
    let mut params = Vec::new();
    let mut unpack = Vec::new();
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
    (params, unpack)
}

/// `::planar_arm::__private::columns` of the row-major outputs of a `rows x cols` matrix, column
/// by column as nalgebra stores it.
pub(crate) fn matrix(rows: usize, cols: usize, ids: &[proc_macro2::Ident]) -> TokenStream {
    let columns = (0..cols).map(|c| {
        let column = (0..rows).map(|r| &ids[r * cols + c]);
        quote!([#(#column),*])
    });
    quote!(::planar_arm::__private::columns([#(#columns),*]))
}

/// `::planar_arm::__private::vector` of the outputs.
pub(crate) fn vector(ids: &[proc_macro2::Ident]) -> TokenStream {
    quote!(::planar_arm::__private::vector([#(#ids),*]))
}
