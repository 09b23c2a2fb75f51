//! A packed derivative program ([`crate::packed`]) as statements: its values as
//! [`render`] writes any program, then one `let` per lane operation through the method's
//! `__lanes: __L` (`::planar_arm::__private::Lanes`: four `f64` in an AVX2 register in the
//! AVX2 copy of the method, an array of four elsewhere), or for a program of eight lanes through
//! `__wide`, the lanes' `Wide` (one AVX-512 register in that copy, two of four elsewhere), then
//! each derivative read from its lane.

use proc_macro2::{Ident, Literal, TokenStream, TokenTree};
use quote::quote;

use super::chunks::chunked;
use crate::emit::{local, render, EmitError, Rendered, Scalar};
use crate::programs::packed::{Lane, Packed};

/// The statements of `pk` and one identifier per derivative.
pub(crate) fn render_packed(pk: &Packed) -> Result<Rendered, EmitError> {
    let values = render(&pk.values, Scalar::F64)?;
    let live = pk.live();
    // Eight lanes (a reverse-mode program) are the lanes' `Wide`.
    let lanes = if pk.width == 8 {
        local("wide")
    } else {
        local("lanes")
    };
    let name = |k: usize| local(&format!("lane{k}"));
    let mut statements: Vec<Vec<TokenTree>> = Vec::new();
    let mut defined: Vec<(usize, Ident)> = Vec::new();
    let mut last_read: Vec<usize> = Vec::new();
    let mut statement_of = vec![usize::MAX; pk.ops.len()];
    let mut bind = |statements: &mut Vec<Vec<TokenTree>>,
                    last_read: &mut Vec<usize>,
                    id: Ident,
                    value: TokenStream,
                    reads: &[usize],
                    last: usize| {
        let at = statements.len();
        for &r in reads {
            last_read[r] = at;
        }
        statements.push(quote!(let #id = #value;).into_iter().collect());
        last_read.push(last);
        defined.push((at, id));
        at
    };
    for (k, op) in pk.ops.iter().enumerate() {
        if !live[k] {
            continue;
        }
        let s = |x: usize| values.outputs[x].clone();
        let (value, reads) = match *op {
            Lane::Const(_) if pk.width != 4 => {
                return Err(EmitError {
                    message: "internal: a constant in a program of eight lanes".to_string(),
                })
            }
            Lane::Const(c) => {
                let c = c.map(|x| Literal::f64_unsuffixed(f64::from(x)));
                (quote!(#lanes.constant([#(#c),*])), vec![])
            }
            Lane::Seed(k, g) => {
                let (w, k, r) = (
                    local("minv"),
                    Literal::usize_unsuffixed(k),
                    Literal::usize_unsuffixed(pk.width * g),
                );
                (
                    quote!(#lanes.constant(::planar_arm::__private::negated_rows(#w, #k, #r))),
                    vec![],
                )
            }
            Lane::Add(a, b) => {
                let (x, y) = (name(a), name(b));
                (
                    quote!(#lanes.add(#x, #y)),
                    vec![statement_of[a], statement_of[b]],
                )
            }
            Lane::Sub(a, b) => {
                let (x, y) = (name(a), name(b));
                (
                    quote!(#lanes.sub(#x, #y)),
                    vec![statement_of[a], statement_of[b]],
                )
            }
            Lane::Neg(a) => {
                let x = name(a);
                (quote!(#lanes.neg(#x)), vec![statement_of[a]])
            }
            Lane::Scale(a, v) => {
                let (x, v) = (name(a), s(v));
                (
                    quote!(#lanes.mul(#x, #lanes.splat(#v))),
                    vec![statement_of[a]],
                )
            }
            Lane::MulAdd(a, v, c) | Lane::NegMulAdd(a, v, c) | Lane::MulSub(a, v, c) => {
                let (x, v, y) = (name(a), s(v), name(c));
                let f = match *op {
                    Lane::MulAdd(..) => quote!(mul_add),
                    Lane::NegMulAdd(..) => quote!(neg_mul_add),
                    _ => quote!(mul_sub),
                };
                (
                    quote!(#lanes.#f(#x, #v, #y)),
                    vec![statement_of[a], statement_of[c]],
                )
            }
        };
        statement_of[k] = bind(&mut statements, &mut last_read, name(k), value, &reads, 0);
    }
    let zero = local("lane_zero");
    let mut outputs = Vec::with_capacity(pk.derivatives.len());
    let mut read_lanes: std::collections::BTreeMap<(usize, usize), Ident> =
        std::collections::BTreeMap::new();
    let mut zero_bound = false;
    for d in &pk.derivatives {
        match *d {
            Some((op, l)) => {
                if let Some(id) = read_lanes.get(&(op, l)) {
                    outputs.push(id.clone());
                    continue;
                }
                let id = local(&format!("lane{op}_{l}"));
                let (x, lit) = (name(op), Literal::usize_unsuffixed(l));
                let reads = [statement_of[op]];
                bind(
                    &mut statements,
                    &mut last_read,
                    id.clone(),
                    quote!(#lanes.lanes(#x)[#lit]),
                    &reads,
                    usize::MAX,
                );
                read_lanes.insert((op, l), id.clone());
                outputs.push(id);
            }
            None => {
                if !zero_bound {
                    bind(
                        &mut statements,
                        &mut last_read,
                        zero.clone(),
                        quote!(0.0_f64),
                        &[],
                        usize::MAX,
                    );
                    zero_bound = true;
                }
                outputs.push(zero.clone());
            }
        }
    }
    let mut all = values.statements;
    if pk.width == 8 {
        let four = local("lanes");
        // The eight lanes' type is `Lanes::Wide` of the body's lanes, whose methods need their
        // trait in scope.
        all.push(quote!(
            use ::planar_arm::__private::Wide as _;
        ));
        all.push(quote!(let #lanes = ::planar_arm::__private::Lanes::wide(#four);));
    }
    all.extend(chunked(statements, 0, &defined, &last_read));
    Ok(Rendered {
        statements: all,
        outputs,
        inputs_used: values.inputs_used,
    })
}
