//! Emission: straight-line Rust for a derived arm.
//!
//! Each generated method is one [`Program`]: inputs are unpacked into named locals, the joint
//! angles that are needed go together to one call of `planar_arm::trig::sin_cos` (a sine and
//! cosine for each, two angles per SIMD register), trig atoms of angle sums are `let`s
//! named like the paper (`c23`), shared subexpressions are `let`s, and everything used once is
//! inlined. Rational constants are written `10.0 / 3.0` so a reader recognises them (the
//! compiler folds the division). All local identifiers carry `Span::mixed_site()`, so they can
//! neither capture nor be captured by the user's items. Output is deterministic.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use num_traits::{Signed, ToPrimitive, Zero};
use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;

use crate::expr::Expr;
use crate::methods::{two, Derived, Method};
use crate::paths::F64;
use crate::poly::Param;
use crate::ring::{show, to_f64, to_i128_pair, Rational};
use crate::slp::{Emit, Id, Input, Node, Program};

/// Why an arm cannot be emitted.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EmitError {
    /// What went wrong, lowercase, naming the fix.
    pub message: String,
}

impl std::fmt::Display for EmitError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for EmitError {}

/// `f64` tokens of an exact constant: `2.0`, `(10.0 / 3.0)`, or the nearest `f64` when the
/// numerator or denominator is not exact in `f64`.
///
/// # Errors
/// If the value is outside the finite `f64` range.
pub fn f64_tokens(r: &Rational) -> Result<TokenStream, EmitError> {
    const EXACT: u64 = 1 << 53;
    let value = to_f64(r).ok_or_else(|| EmitError {
        message: format!("the constant {} does not fit in f64", show(r)),
    })?;
    let magnitude = r.abs();
    let num = magnitude.numer().to_u64().filter(|&v| v <= EXACT);
    let den = magnitude.denom().to_u64().filter(|&v| v <= EXACT);
    let body = match (num, den) {
        #[allow(clippy::cast_precision_loss)] // both are at most 2^53, exact in f64
        (Some(a), Some(1)) => {
            let a = Literal::f64_unsuffixed(a as f64);
            quote!(#a)
        }
        #[allow(clippy::cast_precision_loss)]
        (Some(a), Some(b)) => {
            let (a, b) = (
                Literal::f64_unsuffixed(a as f64),
                Literal::f64_unsuffixed(b as f64),
            );
            quote!((#a / #b))
        }
        _ => {
            let v = Literal::f64_unsuffixed(value.abs());
            quote!(#v)
        }
    };
    Ok(if r.is_negative() {
        quote!((-#body))
    } else {
        body
    })
}

/// Precedence of an emitted expression, to place parentheses.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Prec {
    Sum,
    Product,
    Atom,
}

/// Renders a method's program as `let` statements and the output identifiers.
pub struct Rendered {
    /// The statements, in order.
    pub statements: Vec<TokenStream>,
    /// One identifier per output, in order.
    pub outputs: Vec<Ident>,
    /// Which inputs are read.
    pub inputs_used: std::collections::BTreeSet<Input>,
}

/// A local identifier that neither captures nor is captured by the user's names.
#[must_use]
pub fn local(name: &str) -> Ident {
    if name == "_" {
        return Ident::new(name, Span::mixed_site());
    }
    Ident::new(&format!("__{name}"), Span::mixed_site())
}

/// The local name of an input; a run-time parameter's is `self_` and its field's name.
#[must_use]
pub fn input_name(i: Input, params: &[Param]) -> String {
    match i {
        Input::Param(k) => format!(
            "self_{}",
            params
                .get(k)
                .map_or("", |p| p.name().trim_start_matches("r#"))
        ),
        Input::Q(j) => format!("q{}", j + 1),
        Input::Qd(j) => format!("qd{}", j + 1),
        Input::Qdd(j) => format!("qdd{}", j + 1),
        Input::Tau(j) => format!("tau{}", j + 1),
        Input::Force(0) => "u".into(),
        Input::Force(_) => "v".into(),
        Input::TipTorque => "torque".into(),
        Input::Frozen(k) => format!("frozen{k}"),
    }
}

/// The scalar a method is emitted in.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Scalar {
    /// `f64` throughout.
    F64,
    /// The method's type parameter `__T: ::planar_arm::Real`: constants and parameters enter
    /// through `from_f64`.
    Generic,
}

impl Scalar {
    fn zero(self) -> TokenStream {
        self.constant(quote!(0.0))
    }

    fn constant(self, value: TokenStream) -> TokenStream {
        match self {
            Scalar::F64 => value,
            Scalar::Generic => {
                // `(5.0 / 3.0)` is an argument already: no second pair of parentheses.
                let mut it = value.clone().into_iter();
                let inner = match (it.next(), it.next()) {
                    (Some(proc_macro2::TokenTree::Group(g)), None)
                        if g.delimiter() == proc_macro2::Delimiter::Parenthesis =>
                    {
                        g.stream()
                    }
                    _ => value,
                };
                quote!(__T::from_f64(#inner))
            }
        }
    }
}

/// Renders a method in `scalar`.
///
/// # Errors
/// If a constant does not fit in `f64`.
pub fn render(method: &Method, scalar: Scalar) -> Result<Rendered, EmitError> {
    let p = &method.program;
    let out_ids: Vec<Id> = method.outputs.iter().map(|o| o.1).collect();
    let uses = p.use_counts(&out_ids);
    let mut taken: std::collections::BTreeSet<String> = std::collections::BTreeSet::new();
    let fresh = |base: &str, taken: &mut std::collections::BTreeSet<String>| -> String {
        let mut name = base.to_string();
        let mut k = 2;
        while taken.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        taken.insert(name.clone());
        name
    };
    // Reserve input and per-joint trig names first.
    let mut inputs_used = std::collections::BTreeSet::new();
    let mut joints: BTreeMap<usize, (bool, bool)> = BTreeMap::new();
    for (node, &u) in p.nodes().iter().zip(&uses) {
        if u == 0 {
            continue;
        }
        match *node {
            Node::Input(i) => {
                inputs_used.insert(i);
            }
            Node::Sin(j) => joints.entry(j).or_default().0 = true,
            Node::Cos(j) => joints.entry(j).or_default().1 = true,
            _ => {}
        }
    }
    for &j in joints.keys() {
        inputs_used.insert(Input::Q(j));
    }
    for &i in &inputs_used {
        taken.insert(input_name(i, p.params()));
    }
    for &j in joints.keys() {
        taken.insert(format!("s{}", j + 1));
        taken.insert(format!("c{}", j + 1));
    }
    let output_of: BTreeMap<Id, &str> = method
        .outputs
        .iter()
        .rev()
        .map(|(name, id)| (*id, name.as_str()))
        .collect();

    let mut statements = Vec::new();
    // Run-time parameters are read from their fields once, at the top.
    for &i in &inputs_used {
        if let Input::Param(k) = i {
            let name = local(&input_name(i, p.params()));
            let name_of_field = p.params()[k].name();
            // A raw identifier (`self.r#type`) keeps its `r#`.
            let field = match name_of_field.strip_prefix("r#") {
                Some(raw) => Ident::new_raw(raw, Span::call_site()),
                None => Ident::new(name_of_field, Span::call_site()),
            };
            statements.push(match scalar {
                Scalar::F64 => quote!(let #name: #F64 = self.#field;),
                Scalar::Generic => {
                    quote!(let #name: __T = ::planar_arm::__private::real(self.#field);)
                }
            });
        }
    }
    // Parameter-only values computed beforehand are read from the block.
    for &i in &inputs_used {
        if let Input::Frozen(k) = i {
            let (name, block) = (local(&input_name(i, p.params())), local("block"));
            let k = proc_macro2::Literal::usize_unsuffixed(k);
            statements.push(match scalar {
                Scalar::F64 => quote!(let #name: #F64 = #block.0[#k];),
                Scalar::Generic => {
                    quote!(let #name: __T = ::planar_arm::__private::real(#block.0[#k]);)
                }
            });
        }
    }
    if !joints.is_empty() {
        // One call for all the angles: the kernel evaluates them two at a time in SIMD lanes.
        let mut angles = Vec::new();
        let mut pairs = Vec::new();
        for (&j, &(s, c)) in &joints {
            angles.push(local(&input_name(Input::Q(j), &[])));
            let name = |used: bool, prefix: &str| {
                if used {
                    local(&format!("{prefix}{}", j + 1))
                } else {
                    local("_")
                }
            };
            let (s, c) = (name(s, "s"), name(c, "c"));
            pairs.push(quote!((#s, #c)));
        }
        statements.push(quote!(
            let [#(#pairs),*] = ::planar_arm::__private::sin_cos([#(#angles),*]);
        ));
    }
    let mut exprs: Vec<Option<(Prec, TokenStream)>> = vec![None; p.nodes().len()];
    let mut temp = 0usize;
    // For the chunking of long methods (see `chunked`): the statements after the inputs',
    // which statement each node's expression reads, and each statement's last reader.
    let prefix = statements.len();
    let mut reads: Vec<Vec<usize>> = vec![Vec::new(); p.nodes().len()];
    let mut bound: Vec<Option<usize>> = vec![None; p.nodes().len()];
    let mut last_read: Vec<usize> = vec![0; statements.len()];
    let mut defined: Vec<(usize, Ident)> = Vec::new();
    for (idx, node) in p.nodes().iter().enumerate() {
        if uses[idx] == 0 {
            continue;
        }
        let mut read = Vec::new();
        for c in crate::slp::children(node) {
            match bound[c.0 as usize] {
                Some(s) => read.push(s),
                // An inlined child is read by this node only.
                None => read.append(&mut reads[c.0 as usize]),
            }
        }
        let id = Id(u32::try_from(idx).unwrap_or(u32::MAX));
        let get = |c: Id, exprs: &Vec<Option<(Prec, TokenStream)>>| {
            exprs[c.0 as usize]
                .clone()
                .unwrap_or_else(|| (Prec::Atom, scalar.zero()))
        };
        let paren = |(prec, ts): (Prec, TokenStream), min: Prec| {
            if prec >= min {
                ts
            } else {
                quote!((#ts))
            }
        };
        let (prec, ts) = match node {
            Node::Input(i) => (
                Prec::Atom,
                local(&input_name(*i, p.params())).into_token_stream(),
            ),
            Node::Const(r) => (Prec::Atom, scalar.constant(f64_tokens(r)?)),
            Node::Sin(j) => (
                Prec::Atom,
                local(&format!("s{}", j + 1)).into_token_stream(),
            ),
            Node::Cos(j) => (
                Prec::Atom,
                local(&format!("c{}", j + 1)).into_token_stream(),
            ),
            Node::Add(a, b) => {
                let (a, b) = (
                    paren(get(*a, &exprs), Prec::Sum),
                    paren(get(*b, &exprs), Prec::Sum),
                );
                (Prec::Sum, quote!(#a + #b))
            }
            Node::Sub(a, b) => {
                let a = paren(get(*a, &exprs), Prec::Sum);
                let b = paren(get(*b, &exprs), Prec::Product);
                (Prec::Sum, quote!(#a - #b))
            }
            Node::Mul(a, b) => {
                let (a, b) = (
                    paren(get(*a, &exprs), Prec::Product),
                    paren(get(*b, &exprs), Prec::Product),
                );
                (Prec::Product, quote!(#a * #b))
            }
            Node::Div(a, b) => {
                let a = paren(get(*a, &exprs), Prec::Product);
                let b = paren(get(*b, &exprs), Prec::Atom);
                (Prec::Product, quote!(#a / #b))
            }
            Node::Max(a, b) => match scalar {
                Scalar::F64 => {
                    let a = paren(get(*a, &exprs), Prec::Atom);
                    let (_, b) = get(*b, &exprs);
                    (Prec::Atom, quote!(#a.max(#b)))
                }
                Scalar::Generic => {
                    let ((_, a), (_, b)) = (get(*a, &exprs), get(*b, &exprs));
                    (Prec::Atom, quote!(::planar_arm::__private::max(#a, #b)))
                }
            },
            Node::Neg(a) => {
                let a = paren(get(*a, &exprs), Prec::Atom);
                (Prec::Sum, quote!(-#a))
            }
            Node::Sign(a) => {
                let (_, a) = get(*a, &exprs);
                (Prec::Atom, quote!(::planar_arm::__private::sign(#a)))
            }
        };
        let is_leaf = matches!(
            node,
            Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_)
        );
        let named = p.name(id).is_some() && !is_leaf;
        let is_output = output_of.contains_key(&id);
        if !is_leaf && (uses[idx] > 1 || named || is_output) {
            let base = output_of
                .get(&id)
                .map(|s| (*s).to_string())
                .or_else(|| p.name(id).map(str::to_string))
                .unwrap_or_else(|| {
                    temp += 1;
                    format!("t{temp}")
                });
            let name = local(&fresh(&base, &mut taken));
            let at = statements.len();
            for &r in &read {
                last_read[r] = at;
            }
            statements.push(quote!(let #name = #ts;));
            last_read.push(0);
            defined.push((at, name.clone()));
            bound[idx] = Some(at);
            exprs[idx] = Some((Prec::Atom, name.into_token_stream()));
        } else {
            reads[idx] = read;
            exprs[idx] = Some((prec, ts));
        }
    }
    let mut outputs = Vec::new();
    for (name, id) in &method.outputs {
        let (_, ts) = exprs[id.0 as usize]
            .clone()
            .unwrap_or_else(|| (Prec::Atom, scalar.zero()));
        let k = id.0 as usize;
        // Leaves and repeated outputs (the symmetric half of M) get their own readable let.
        let ident = match syn_ident(&ts) {
            Some(existing) => {
                if let Some(s) = bound[k] {
                    last_read[s] = usize::MAX;
                }
                existing
            }
            None => {
                let ident = local(&fresh(name, &mut taken));
                let at = statements.len();
                for &r in &reads[k] {
                    last_read[r] = at;
                }
                statements.push(quote!(let #ident = #ts;));
                last_read.push(usize::MAX);
                defined.push((at, ident.clone()));
                bound[k] = Some(at);
                exprs[k] = Some((Prec::Atom, ident.clone().into_token_stream()));
                ident
            }
        };
        outputs.push(ident);
    }
    Ok(Rendered {
        statements: chunked(statements, prefix, &defined, &last_read),
        outputs,
        inputs_used,
    })
}

/// The most `let`s in one block of a generated method.
///
/// Each `let` opens a scope that nests until the end of its block, and LLVM builds the debug
/// information of nested scopes recursively: a method of several thousand `let`s (the
/// regressor of a 30-link arm has 4,000) overflowed rustc's stack in a `dev` build
/// (`debuginfo = 2`), where 2,700 still compiled.
const CHUNK: usize = 1000;

/// `statements[prefix..]` in blocks of at most [`CHUNK`] `let`s, each block handing on what
/// later statements read: `let (a, b, ...) = { ...; (a, b, ...) };`. Methods of fewer
/// statements are left as they are.
fn chunked(
    statements: Vec<TokenStream>,
    prefix: usize,
    defined: &[(usize, Ident)],
    last_read: &[usize],
) -> Vec<TokenStream> {
    if statements.len() - prefix <= CHUNK {
        return statements;
    }
    let name_of: BTreeMap<usize, &Ident> = defined.iter().map(|(s, i)| (*s, i)).collect();
    let mut out = Vec::new();
    let mut it = statements.into_iter().enumerate().peekable();
    while let Some((_, st)) = it.next_if(|(s, _)| *s < prefix) {
        out.push(st);
    }
    let rest: Vec<(usize, TokenStream)> = it.collect();
    for chunk in rest.chunks(CHUNK) {
        let end = chunk.last().map_or(0, |c| c.0 + 1);
        let handed: Vec<&Ident> = chunk
            .iter()
            .filter(|(s, _)| last_read[*s] >= end)
            .filter_map(|(s, _)| name_of.get(s).copied())
            .collect();
        let body = chunk.iter().map(|(_, st)| st);
        out.push(quote!(let (#(#handed,)*) = { #(#body)* (#(#handed,)*) };));
    }
    out
}

use quote::ToTokens as _;

/// The identifier, if the tokens are a single identifier.
fn syn_ident(ts: &TokenStream) -> Option<Ident> {
    let mut it = ts.clone().into_iter();
    match (it.next(), it.next()) {
        (Some(proc_macro2::TokenTree::Ident(i)), None) => Some(i),
        _ => None,
    }
}

/// An `f64` expression of a coefficient: a literal such as `(10.0 / 3.0)`, or for one with
/// run-time parameters a block that reads them from `self` and evaluates the polynomial.
///
/// # Errors
/// If a constant does not fit in `f64`.
pub fn coefficient_tokens<C: Emit>(c: &C) -> Result<TokenStream, EmitError> {
    if let Some(r) = c.rational() {
        return f64_tokens(&r);
    }
    let mut p = Program::new();
    let id = p.coefficient(c);
    let rendered = render(
        &Method {
            program: p,
            outputs: vec![("value".into(), id)],
            evaluation: String::new(),
        },
        Scalar::F64,
    )?;
    let statements = &rendered.statements;
    let out = &rendered.outputs[0];
    Ok(quote!({ #(#statements)* #out }))
}

/// Human-readable formulas for a method's doc comment.
#[must_use]
pub fn formula_doc<C: Emit>(title: &str, rows: &[(String, &Expr<C>)]) -> String {
    let terms: usize = rows.iter().map(|(_, e)| e.len()).sum();
    if terms > DOC_TERMS {
        // Formulas this long are not read in rustdoc, and formatting them costs every user
        // compile time (see `DOC_TERMS`).
        return format!(
            "{title}\n\nThe exact formulas have {terms} terms, more than the {DOC_TERMS} shown \
             in the documentation; `PlanarArm::EXACT` holds M, c, g, T and V exactly \
             (each entry prints with `Display`), and `planar_arm::symbolic` (feature \
             `symbolic`) derives them."
        );
    }
    let mut s = format!("{title}\n\n```text\n");
    for (name, e) in rows {
        let _ = writeln!(s, "{name} = {e}");
    }
    s.push_str("```\n");
    s
}

/// The most terms a method's documentation prints: every formula of an arm of up to four
/// links; at six links the longest (736 terms) is left to `EXACT`. Formatting the formulas,
/// and expanding C only to print it, was a fifth of an unoptimised 6-link derive at 2,000.
pub const DOC_TERMS: usize = 500;

/// Fails if a derived coefficient cannot be emitted as `const` data (`i128`) or as `f64`.
///
/// # Errors
/// Names the first entry whose coefficient does not fit.
pub fn check_representable<C: Emit>(d: &Derived<C>) -> Result<(), EmitError> {
    let check = |what: &str, e: &Expr<C>| -> Result<(), EmitError> {
        for (_, _, c) in e
            .terms()
            .flat_map(|(m, t, c)| c.parts().into_iter().map(move |(_, r)| (m, t, r)))
        {
            let c = &c;
            if to_i128_pair(c).is_none() || to_f64(c).is_none() || c.is_zero() {
                return Err(EmitError {
                    message: format!(
                        "the exact coefficient {} in {what} does not fit in i128 and f64; \
                         choose link parameters with smaller numerators and denominators",
                        show(c)
                    ),
                });
            }
        }
        Ok(())
    };
    check("the kinetic energy", &d.dynamics.kinetic_energy)?;
    check("the potential energy", &d.dynamics.potential_energy)?;
    for (i, row) in d.dynamics.mass_matrix.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            check(&format!("M{}", two(i, j)), e)?;
        }
    }
    for (i, e) in d.dynamics.coriolis.iter().enumerate() {
        check(&format!("c{}", i + 1), e)?;
    }
    for (i, e) in d.dynamics.gravity.iter().enumerate() {
        check(&format!("g{}", i + 1), e)?;
    }
    Ok(())
}
