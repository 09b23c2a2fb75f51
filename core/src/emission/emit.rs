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

use proc_macro2::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream, TokenTree};
use quote::quote;

use super::chunks::chunked;
use super::tokens::{constant_inner, path, punct, wrapped};
use crate::methods::Method;
use crate::poly::Param;
use crate::ring::Rational;
use crate::slp::{Emit, Id, Input, Node, Program};

pub use super::error::EmitError;
pub use super::formulas::{check_representable, formula_doc, long_formula_doc, DOC_TERMS};
pub(crate) use super::tokens::f64_argument_tokens;
pub use super::tokens::f64_tokens;

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
    /// A constant in this scalar: `(10.0 / 3.0)` or `__T::from_f64(10.0 / 3.0)`.
    fn constant(self, r: &Rational) -> Result<Vec<TokenTree>, EmitError> {
        Ok(self.of_f64(constant_inner(r)?))
    }

    fn zero(self) -> Vec<TokenTree> {
        self.of_f64(vec![Literal::f64_unsuffixed(0.0).into()])
    }

    /// An `f64` expression (without outer parentheses) as a value of this scalar.
    fn of_f64(self, inner: Vec<TokenTree>) -> Vec<TokenTree> {
        match self {
            Scalar::F64 => wrapped(inner),
            Scalar::Generic => vec![
                Ident::new("__T", Span::call_site()).into(),
                Punct::new(':', Spacing::Joint).into(),
                Punct::new(':', Spacing::Alone).into(),
                Ident::new("from_f64", Span::call_site()).into(),
                Group::new(Delimiter::Parenthesis, inner.into_iter().collect()).into(),
            ],
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

    // Each statement is a list of token trees, and the body becomes a token stream once, at
    // the end: built operator by operator with `quote!`, every node cost a few calls across the
    // compiler's procedural-macro bridge, half of the expansion of a 6-link arm.
    let mut statements: Vec<Vec<TokenTree>> = Vec::new();
    let let_ = || -> TokenTree { Ident::new("let", Span::call_site()).into() };
    let self_ = || -> TokenTree { Ident::new("self", Span::call_site()).into() };
    // `let name: f64 = read;`, or in a generic method `let name: __T = real(read);`.
    let read_f64 = |name: Ident, read: Vec<TokenTree>| {
        let mut st = vec![let_(), name.into(), punct(':')];
        match scalar {
            Scalar::F64 => {
                st.extend(path(&["core", "primitive", "f64"]));
                st.push(punct('='));
                st.extend(read);
            }
            Scalar::Generic => {
                st.push(Ident::new("__T", Span::call_site()).into());
                st.push(punct('='));
                st.extend(path(&["planar_arm", "__private", "real"]));
                st.push(Group::new(Delimiter::Parenthesis, read.into_iter().collect()).into());
            }
        }
        st.push(punct(';'));
        st
    };
    // Run-time parameters are read from their fields once, at the top.
    for &i in &inputs_used {
        if let Input::Param(k) = i {
            let name = local(&input_name(i, p.params()));
            let name_of_field = p.params()[k].name();
            // Through the derive's accessor (`crate::paths::param_accessor`): a field of the
            // wrong type is then one error at the field, not one at each read.
            let accessor = crate::paths::param_accessor(name_of_field);
            let call = Group::new(Delimiter::Parenthesis, TokenStream::new());
            let read = vec![self_(), punct('.'), accessor.into(), call.into()];
            statements.push(read_f64(name, read));
        }
    }
    // Parameter-only values computed beforehand are read from the block.
    for &i in &inputs_used {
        if let Input::Frozen(k) = i {
            let (name, block) = (local(&input_name(i, p.params())), local("block"));
            let k = proc_macro2::Literal::usize_unsuffixed(k);
            let read = vec![
                block.into(),
                punct('.'),
                Literal::usize_unsuffixed(0).into(),
                Group::new(Delimiter::Bracket, TokenTree::from(k).into()).into(),
            ];
            statements.push(read_f64(name, read));
        }
    }
    if !joints.is_empty() {
        // One call for all the angles: the kernel evaluates them in SIMD lanes.
        let mut angles = Vec::new();
        let mut pairs = Vec::new();
        for (k, (&j, &(s, c))) in joints.iter().enumerate() {
            if k > 0 {
                angles.push(punct(','));
                pairs.push(punct(','));
            }
            angles.push(local(&input_name(Input::Q(j), &[])).into());
            let name = |used: bool, prefix: &str| {
                if used {
                    local(&format!("{prefix}{}", j + 1))
                } else {
                    local("_")
                }
            };
            let pair = [name(s, "s").into(), punct(','), name(c, "c").into()];
            pairs.push(Group::new(Delimiter::Parenthesis, pair.into_iter().collect()).into());
        }
        let mut st = vec![
            let_(),
            Group::new(Delimiter::Bracket, pairs.into_iter().collect()).into(),
            punct('='),
        ];
        st.extend(path(&["planar_arm", "__private", "sin_cos"]));
        let angles = Group::new(Delimiter::Bracket, angles.into_iter().collect());
        st.push(Group::new(Delimiter::Parenthesis, TokenTree::from(angles).into()).into());
        st.push(punct(';'));
        statements.push(st);
    }
    let assign = |name: &Ident, mut value: Vec<TokenTree>| {
        let mut st = Vec::with_capacity(value.len() + 4);
        st.push(let_());
        st.push(name.clone().into());
        st.push(punct('='));
        st.append(&mut value);
        st.push(punct(';'));
        st
    };
    let mut exprs: Vec<Option<(Prec, Vec<TokenTree>)>> = vec![None; p.nodes().len()];
    let mut temp = 0usize;
    // For the chunking of long methods (see `chunked`): the statements after the inputs',
    // which statement each node's expression reads, and each statement's last reader.
    let prefix = statements.len();
    let mut reads: Vec<Vec<usize>> = vec![Vec::new(); p.nodes().len()];
    let mut bound: Vec<Option<usize>> = vec![None; p.nodes().len()];
    let mut last_read: Vec<usize> = vec![0; statements.len()];
    let mut defined: Vec<(usize, Ident)> = Vec::new();
    let is_leaf = |node: &Node| {
        matches!(
            node,
            Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_)
        )
    };
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
        // A child that is neither a leaf nor bound to a `let` is read once, here: its tokens
        // move into this expression.
        let mut get = |c: Id| {
            let k = c.0 as usize;
            let e = if bound[k].is_some() || is_leaf(&p.nodes()[k]) {
                exprs[k].clone()
            } else {
                exprs[k].take()
            };
            e.unwrap_or_else(|| (Prec::Atom, scalar.zero()))
        };
        let paren = |(prec, ts): (Prec, Vec<TokenTree>), min: Prec| {
            if prec >= min {
                ts
            } else {
                vec![Group::new(Delimiter::Parenthesis, ts.into_iter().collect()).into()]
            }
        };
        let binary = |a: Vec<TokenTree>, op: char, b: Vec<TokenTree>| {
            let mut out = a;
            out.push(punct(op));
            out.extend(b);
            out
        };
        let call = |mut f: Vec<TokenTree>, args: Vec<TokenTree>| {
            f.push(Group::new(Delimiter::Parenthesis, args.into_iter().collect()).into());
            f
        };
        let (prec, ts) = match node {
            Node::Input(i) => (Prec::Atom, vec![local(&input_name(*i, p.params())).into()]),
            Node::Const(r) => (Prec::Atom, scalar.constant(r)?),
            Node::Sin(j) => (Prec::Atom, vec![local(&format!("s{}", j + 1)).into()]),
            Node::Cos(j) => (Prec::Atom, vec![local(&format!("c{}", j + 1)).into()]),
            Node::Add(a, b) => {
                let a = paren(get(*a), Prec::Sum);
                let b = paren(get(*b), Prec::Sum);
                (Prec::Sum, binary(a, '+', b))
            }
            Node::Sub(a, b) => {
                let a = paren(get(*a), Prec::Sum);
                let b = paren(get(*b), Prec::Product);
                (Prec::Sum, binary(a, '-', b))
            }
            Node::Mul(a, b) => {
                let a = paren(get(*a), Prec::Product);
                let b = paren(get(*b), Prec::Product);
                (Prec::Product, binary(a, '*', b))
            }
            Node::Div(a, b) => {
                let a = paren(get(*a), Prec::Product);
                let b = paren(get(*b), Prec::Atom);
                (Prec::Product, binary(a, '/', b))
            }
            Node::Max(a, b) => match scalar {
                Scalar::F64 => {
                    let mut a = paren(get(*a), Prec::Atom);
                    let (_, b) = get(*b);
                    a.push(punct('.'));
                    a.push(Ident::new("max", Span::call_site()).into());
                    (Prec::Atom, call(a, b))
                }
                Scalar::Generic => {
                    let (_, mut a) = get(*a);
                    let (_, b) = get(*b);
                    a.push(punct(','));
                    a.extend(b);
                    (
                        Prec::Atom,
                        call(path(&["planar_arm", "__private", "max"]), a),
                    )
                }
            },
            Node::Neg(a) => {
                let a = paren(get(*a), Prec::Atom);
                (Prec::Sum, binary(Vec::new(), '-', a))
            }
            Node::Sign(a) => {
                let (_, a) = get(*a);
                (
                    Prec::Atom,
                    call(path(&["planar_arm", "__private", "sign"]), a),
                )
            }
        };
        let leaf = is_leaf(node);
        let named = p.name(id).is_some() && !leaf;
        let is_output = output_of.contains_key(&id);
        if !leaf && (uses[idx] > 1 || named || is_output) {
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
            statements.push(assign(&name, ts));
            last_read.push(0);
            exprs[idx] = Some((Prec::Atom, vec![name.clone().into()]));
            defined.push((at, name));
            bound[idx] = Some(at);
        } else {
            reads[idx] = read;
            exprs[idx] = Some((prec, ts));
        }
    }
    let mut outputs = Vec::new();
    for (name, id) in &method.outputs {
        let k = id.0 as usize;
        let (_, ts) = exprs[k]
            .clone()
            .unwrap_or_else(|| (Prec::Atom, scalar.zero()));
        // Leaves and repeated outputs (the symmetric half of M) get their own readable let.
        let ident = match ts.as_slice() {
            [TokenTree::Ident(existing)] => {
                if let Some(s) = bound[k] {
                    last_read[s] = usize::MAX;
                }
                existing.clone()
            }
            _ => {
                let ident = local(&fresh(name, &mut taken));
                let at = statements.len();
                for &r in &reads[k] {
                    last_read[r] = at;
                }
                statements.push(assign(&ident, ts));
                last_read.push(usize::MAX);
                defined.push((at, ident.clone()));
                bound[k] = Some(at);
                exprs[k] = Some((Prec::Atom, vec![ident.clone().into()]));
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
