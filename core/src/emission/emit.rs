//! Emission: straight-line Rust for a derived arm.
//!
//! Each generated method is one [`Program`]: inputs are unpacked into named locals, the joint
//! angles that are needed go together to one call of `planar_arm::trig::sin_cos` (a sine and
//! cosine for each, two angles per SIMD register), trig atoms of angle sums are `let`s
//! named like the paper (`c23`), shared subexpressions are `let`s, and everything used once is
//! inlined. Rational constants are written `10.0 / 3.0` so a reader recognises them (the
//! compiler folds the division). All local identifiers carry `Span::mixed_site()`, so they can
//! neither capture nor be captured by the user's items. Output is deterministic.

use std::collections::{BTreeMap, BTreeSet};

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
pub use super::tokens::{f64_tokens, f64_value_tokens};

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
        Input::Virtual(j) => format!("virtual{}", j + 1),
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
    let (inputs_used, joints) = inputs(p, &uses);
    let output_of: BTreeMap<Id, &str> = method
        .outputs
        .iter()
        .rev()
        .map(|(name, id)| (*id, name.as_str()))
        .collect();
    let mut body = Body::new(p, scalar, prologue(p, scalar, &inputs_used, &joints));
    body.reserve(&inputs_used, &joints);
    for (idx, node) in p.nodes().iter().enumerate() {
        if uses[idx] > 0 {
            body.node(idx, node, uses[idx], &output_of)?;
        }
    }
    let outputs = method
        .outputs
        .iter()
        .map(|(name, id)| body.output(name, *id))
        .collect();
    Ok(Rendered {
        statements: chunked(body.statements, body.prefix, &body.defined, &body.last_read),
        outputs,
        inputs_used,
    })
}

/// The inputs the used nodes read, and per joint whether its sine and cosine are used (its
/// angle is then read too).
fn inputs(p: &Program, uses: &[usize]) -> (BTreeSet<Input>, BTreeMap<usize, (bool, bool)>) {
    let mut inputs_used = BTreeSet::new();
    let mut joints: BTreeMap<usize, (bool, bool)> = BTreeMap::new();
    for (node, &u) in p.nodes().iter().zip(uses) {
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
    (inputs_used, joints)
}

fn let_() -> TokenTree {
    Ident::new("let", Span::call_site()).into()
}

/// The statements before the body: the run-time parameters read from their fields once, the
/// parameter-only values read from the frozen block, and one `sin_cos` call for the angles.
fn prologue(
    p: &Program,
    scalar: Scalar,
    inputs_used: &BTreeSet<Input>,
    joints: &BTreeMap<usize, (bool, bool)>,
) -> Vec<Vec<TokenTree>> {
    let mut statements: Vec<Vec<TokenTree>> = Vec::new();
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
    for &i in inputs_used {
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
    for &i in inputs_used {
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
        statements.push(sin_cos(joints));
    }
    statements
}

/// `let [(s1, c1), (s2, _), ...] = sin_cos([q1, q2, ...]);`: one call for all the angles, whose
/// kernel evaluates them in SIMD lanes.
fn sin_cos(joints: &BTreeMap<usize, (bool, bool)>) -> Vec<TokenTree> {
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
    st
}

/// An expression's tokens and its precedence.
type Tokens = (Prec, Vec<TokenTree>);

fn is_leaf(node: &Node) -> bool {
    matches!(
        node,
        Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_)
    )
}

/// A method's body as it is written.
///
/// Each statement is a list of token trees, and the body becomes a token stream once, at the
/// end: built operator by operator with `quote!`, every node cost a few calls across the
/// compiler's procedural-macro bridge, half of the expansion of a 6-link arm.
struct Body<'p> {
    p: &'p Program,
    scalar: Scalar,
    statements: Vec<Vec<TokenTree>>,
    /// The statements before this one read the inputs.
    prefix: usize,
    /// The local names in use.
    taken: BTreeSet<String>,
    /// Temporaries named so far.
    temp: usize,
    /// Each node's expression: the name of its `let`, or its tokens until the one node that
    /// reads them takes them.
    exprs: Vec<Option<Tokens>>,
    /// For the chunking of long methods (see `chunked`): which statements each inlined
    /// expression reads, the statement each node is bound to, each statement's last reader,
    /// and the names the statements bind.
    reads: Vec<Vec<usize>>,
    bound: Vec<Option<usize>>,
    last_read: Vec<usize>,
    defined: Vec<(usize, Ident)>,
}

impl<'p> Body<'p> {
    fn new(p: &'p Program, scalar: Scalar, prologue: Vec<Vec<TokenTree>>) -> Self {
        let nodes = p.nodes().len();
        Self {
            p,
            scalar,
            prefix: prologue.len(),
            last_read: vec![0; prologue.len()],
            statements: prologue,
            taken: BTreeSet::new(),
            temp: 0,
            exprs: vec![None; nodes],
            reads: vec![Vec::new(); nodes],
            bound: vec![None; nodes],
            defined: Vec::new(),
        }
    }

    /// Reserves the inputs' and the per-joint trig names before any other.
    fn reserve(&mut self, inputs_used: &BTreeSet<Input>, joints: &BTreeMap<usize, (bool, bool)>) {
        for &i in inputs_used {
            self.taken.insert(input_name(i, self.p.params()));
        }
        for &j in joints.keys() {
            self.taken.insert(format!("s{}", j + 1));
            self.taken.insert(format!("c{}", j + 1));
        }
    }

    /// `base`, or `base_2`, `base_3`, ... if it is taken; now taken.
    fn fresh(&mut self, base: &str) -> String {
        let mut name = base.to_string();
        let mut k = 2;
        while self.taken.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        self.taken.insert(name.clone());
        name
    }

    /// Appends `let name = value;`, which reads the statements `read`, with `last` as its
    /// last reader so far; `idx`'s expression is now the name.
    fn bind(
        &mut self,
        idx: usize,
        name: Ident,
        value: Vec<TokenTree>,
        read: &[usize],
        last: usize,
    ) {
        let at = self.statements.len();
        for &r in read {
            self.last_read[r] = at;
        }
        let mut st = Vec::with_capacity(value.len() + 4);
        st.push(let_());
        st.push(name.clone().into());
        st.push(punct('='));
        st.extend(value);
        st.push(punct(';'));
        self.statements.push(st);
        self.last_read.push(last);
        self.exprs[idx] = Some((Prec::Atom, vec![name.clone().into()]));
        self.defined.push((at, name));
        self.bound[idx] = Some(at);
    }

    /// Operand `c` of the node being written. A child that is neither a leaf nor bound to a
    /// `let` is read once, here: its tokens move into the reader's expression.
    fn operand(&mut self, c: Id) -> Tokens {
        let k = c.0 as usize;
        let e = if self.bound[k].is_some() || is_leaf(&self.p.nodes()[k]) {
            self.exprs[k].clone()
        } else {
            self.exprs[k].take()
        };
        e.unwrap_or_else(|| (Prec::Atom, self.scalar.zero()))
    }

    /// Writes node `idx`, used `uses` times: bound to a `let` when it is used more than once,
    /// named or an output, inlined into its reader otherwise.
    fn node(
        &mut self,
        idx: usize,
        node: &Node,
        uses: usize,
        output_of: &BTreeMap<Id, &str>,
    ) -> Result<(), EmitError> {
        let mut read = Vec::new();
        for c in crate::slp::children(node) {
            match self.bound[c.0 as usize] {
                Some(s) => read.push(s),
                // An inlined child is read by this node only.
                None => read.append(&mut self.reads[c.0 as usize]),
            }
        }
        let id = Id(u32::try_from(idx).unwrap_or(u32::MAX));
        let (p, scalar) = (self.p, self.scalar);
        let (prec, ts) = expression(node, p, scalar, &mut |c| self.operand(c))?;
        let leaf = is_leaf(node);
        let named = p.name(id).is_some() && !leaf;
        if !leaf && (uses > 1 || named || output_of.contains_key(&id)) {
            let base = output_of
                .get(&id)
                .map(|s| (*s).to_string())
                .or_else(|| p.name(id).map(str::to_string))
                .unwrap_or_else(|| {
                    self.temp += 1;
                    format!("t{}", self.temp)
                });
            let name = local(&self.fresh(&base));
            self.bind(idx, name, ts, &read, 0);
        } else {
            self.reads[idx] = read;
            self.exprs[idx] = Some((prec, ts));
        }
        Ok(())
    }

    /// The identifier of output `name`, node `id`. Leaves and repeated outputs (the symmetric
    /// half of M) get their own readable `let`.
    fn output(&mut self, name: &str, id: Id) -> Ident {
        let k = id.0 as usize;
        let (_, ts) = self.exprs[k]
            .clone()
            .unwrap_or_else(|| (Prec::Atom, self.scalar.zero()));
        if let [TokenTree::Ident(existing)] = ts.as_slice() {
            if let Some(s) = self.bound[k] {
                self.last_read[s] = usize::MAX;
            }
            return existing.clone();
        }
        let ident = local(&self.fresh(name));
        let read = std::mem::take(&mut self.reads[k]);
        self.bind(k, ident.clone(), ts, &read, usize::MAX);
        self.reads[k] = read;
        ident
    }
}

/// The tokens of `node`'s expression and their precedence, its operands from `operand`.
fn expression(
    node: &Node,
    p: &Program,
    scalar: Scalar,
    operand: &mut dyn FnMut(Id) -> Tokens,
) -> Result<Tokens, EmitError> {
    let paren = |(prec, ts): Tokens, min: Prec| {
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
    Ok(match node {
        Node::Input(i) => (Prec::Atom, vec![local(&input_name(*i, p.params())).into()]),
        Node::Const(r) => (Prec::Atom, scalar.constant(r)?),
        Node::Sin(j) => (Prec::Atom, vec![local(&format!("s{}", j + 1)).into()]),
        Node::Cos(j) => (Prec::Atom, vec![local(&format!("c{}", j + 1)).into()]),
        Node::Add(a, b) => {
            let a = paren(operand(*a), Prec::Sum);
            let b = paren(operand(*b), Prec::Sum);
            (Prec::Sum, binary(a, '+', b))
        }
        Node::Sub(a, b) => {
            let a = paren(operand(*a), Prec::Sum);
            let b = paren(operand(*b), Prec::Product);
            (Prec::Sum, binary(a, '-', b))
        }
        Node::Mul(a, b) => {
            let a = paren(operand(*a), Prec::Product);
            let b = paren(operand(*b), Prec::Product);
            (Prec::Product, binary(a, '*', b))
        }
        Node::Div(a, b) => {
            let a = paren(operand(*a), Prec::Product);
            let b = paren(operand(*b), Prec::Atom);
            (Prec::Product, binary(a, '/', b))
        }
        Node::Max(a, b) => match scalar {
            Scalar::F64 => {
                let mut a = paren(operand(*a), Prec::Atom);
                let (_, b) = operand(*b);
                a.push(punct('.'));
                a.push(Ident::new("max", Span::call_site()).into());
                (Prec::Atom, call(a, b))
            }
            Scalar::Generic => {
                let (_, mut a) = operand(*a);
                let (_, b) = operand(*b);
                a.push(punct(','));
                a.extend(b);
                (
                    Prec::Atom,
                    call(path(&["planar_arm", "__private", "max"]), a),
                )
            }
        },
        Node::Neg(a) => {
            let a = paren(operand(*a), Prec::Atom);
            (Prec::Sum, binary(Vec::new(), '-', a))
        }
        Node::Sign(a) => {
            let (_, a) = operand(*a);
            (
                Prec::Atom,
                call(path(&["planar_arm", "__private", "sign"]), a),
            )
        }
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
            packed: None,
        },
        Scalar::F64,
    )?;
    let statements = &rendered.statements;
    let out = &rendered.outputs[0];
    Ok(quote!({ #(#statements)* #out }))
}
