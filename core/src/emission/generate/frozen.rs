//! The hot methods of an arm with run-time parameters, split at their parameter-only frontier
//! ([`crate::frozen`]): a block of parameter-only values that `__freeze` computes from the
//! fields, and hidden variants of the hot methods that read it, which the plain methods call.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emission::function::{emit_fn, forwarder, Fn, FrozenVariant, Param};
use crate::emit::{local, render, EmitError, Scalar};
use crate::frozen::{freeze, Frozen};
use crate::methods::Method;
use crate::slp::{Id, Input, Node};

/// The methods that get a variant reading a frozen block: what simulators and controllers
/// call every cycle.
const HOT: [&str; 5] = [
    "mass_matrix",
    "bias",
    "mass_matrix_and_bias",
    "inverse_dynamics",
    "forward_dynamics",
];

/// Whether the plain hot method `name` of an arm of `n` joints with run-time parameters is
/// emitted as a call of its frozen variant ([`frozen_wrapper`]). Measured, one run each,
/// interleaved, against their own bodies: 0.96-1.03x at three to six links; `mass_matrix`
/// 1.04-1.12x there, so it keeps its body; at two links `mass_matrix_and_bias` 1.06-1.09x, so
/// they all do.
fn calls_frozen(n: usize, name: &str) -> bool {
    n >= 3 && name != "mass_matrix"
}

/// The hot methods among `programs`, in order.
pub(crate) fn hot<'t, 'a>(programs: &'t [Fn<'a>]) -> Vec<&'t Fn<'a>> {
    programs.iter().filter(|f| HOT.contains(&f.name)).collect()
}

/// The hot methods split at their parameter-only frontier, or `None` for an all-literal arm,
/// whose constants are folded already.
pub(crate) fn split(hot: &[&Fn<'_>]) -> Option<Frozen> {
    if hot.iter().any(|f| !f.method.program.params().is_empty()) {
        let methods: Vec<Method> = hot.iter().map(|f| f.method.clone()).collect();
        freeze(&methods)
    } else {
        None
    }
}

/// The plain method `f`: its program, or for a hot method that [`calls_frozen`], the call.
pub(crate) fn plain(
    n: usize,
    f: &Fn<'_>,
    hot: &[&Fn<'_>],
    frozen: Option<&Frozen>,
) -> Result<TokenStream, EmitError> {
    let variant = frozen.filter(|_| calls_frozen(n, f.name)).and_then(|fz| {
        hot.iter()
            .position(|h| h.name == f.name)
            .map(|i| (&fz.methods[i], &fz.block))
    });
    match variant {
        Some((m, block)) => frozen_wrapper(n, f, m, block),
        None => emit_fn(n, f, None),
    }
}

/// A hot method of an arm with run-time parameters as the parameter-only values its frozen
/// variant `m` reads (computed from the fields, the block's other slots 0.0) followed by a
/// call of that variant: the state-dependent code is written once, in `__NAME_frozen`,
/// instead of twice.
fn frozen_wrapper(
    n: usize,
    f: &Fn<'_>,
    m: &Method,
    block: &Method,
) -> Result<TokenStream, EmitError> {
    let outs: Vec<Id> = m.outputs.iter().map(|o| o.1).collect();
    let uses = m.program.use_counts(&outs);
    let read: std::collections::BTreeSet<usize> = m
        .program
        .nodes()
        .iter()
        .zip(&uses)
        .filter_map(|(node, &u)| match node {
            Node::Input(Input::Frozen(k)) if u > 0 => Some(*k),
            _ => None,
        })
        .collect();
    let part = Method {
        program: block.program.clone(),
        outputs: read.iter().map(|&k| block.outputs[k].clone()).collect(),
        evaluation: String::new(),
        packed: None,
    };
    let rendered = render(&part, Scalar::F64)?;
    let mut values = rendered.outputs.iter();
    let slots = (0..block.outputs.len()).map(|k| {
        if read.contains(&k) {
            let v = values.next();
            quote!(#v)
        } else {
            quote!(0.0)
        }
    });
    let statements = &rendered.statements;
    let cost = m.op_count() + part.op_count();
    let evaluation = if f.method.evaluation.is_empty() {
        String::new()
    } else {
        format!("{}\n\n", f.method.evaluation)
    };
    let doc = format!("{}\n\n{evaluation}Cost: {cost}.", f.doc);
    let name = quote::format_ident!("{}", f.name);
    let frozen = quote::format_ident!("__{}_frozen", f.name);
    let nn = Literal::usize_unsuffixed(n);
    let args = f
        .params
        .iter()
        .map(|p| match *p {
            Param::Joints(name, _) => Ok(local(name)),
            Param::Force | Param::Torque => Err(EmitError {
                message: format!("internal: `{}` is frozen but takes a tip load", f.name),
            }),
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let ret = &f.ret;
    let touch = &f.touch;
    let b = local("block");
    let (head, wrapper) = if f.inlined_body {
        let body = f.body_name();
        (
            quote!(#[doc(hidden)] #[inline(always)] fn #body),
            forwarder(
                n,
                f,
                quote!(#[doc = #doc] #[inline] fn #name<__T: ::planar_arm::Real>),
            )?,
        )
    } else {
        (quote!(#[doc = #doc] #[inline] fn #name), TokenStream::new())
    };
    Ok(quote! {
        #wrapper
        #head<__T: ::planar_arm::Real>(
            &self, #(#args: &::planar_arm::nalgebra::SVector<__T, #nn>),*
        ) -> #ret {
            #touch
            #(#statements)*
            let #b = ::planar_arm::__private::Block([#(#slots),*]);
            self.#frozen(&#b, #(#args),*)
        }
    })
}

/// `type __Frozen`, the block's type (of no slots for an all-literal arm), and with a frozen
/// split the hot methods' variants and `__freeze`, which computes the block.
pub(crate) fn variants(
    n: usize,
    hot: &[&Fn<'_>],
    frozen: Option<&Frozen>,
) -> Result<Vec<TokenStream>, EmitError> {
    let slots = frozen.map_or(0, |fz| fz.block.outputs.len());
    let slots_lit = Literal::usize_unsuffixed(slots);
    let mut items = vec![quote!(
        #[doc(hidden)]
        type __Frozen = ::planar_arm::__private::Block<#slots_lit>;
    )];
    let Some(fz) = frozen else {
        return Ok(items);
    };
    for (f, m) in hot.iter().zip(&fz.methods) {
        let variant = FrozenVariant {
            method: m,
            slots,
            is_body: calls_frozen(n, f.name),
        };
        items.push(emit_fn(n, f, Some(variant))?);
    }
    let rendered = render(&fz.block, Scalar::F64)?;
    let statements = &rendered.statements;
    let outputs = &rendered.outputs;
    let names: Vec<&str> = hot.iter().map(|f| f.name).collect();
    let doc = format!(
        "The parameter-only values of `{}`, from the arm's fields. Cost: {}.",
        names.join("`, `"),
        fz.block.op_count()
    );
    items.push(quote!(
        #[doc = #doc]
        #[doc(hidden)]
        #[inline]
        fn __freeze(&self) -> ::planar_arm::__private::Block<#slots_lit> {
            #(#statements)*
            ::planar_arm::__private::Block([#(#outputs),*])
        }
    ));
    Ok(items)
}
