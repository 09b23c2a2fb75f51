//! The program: its nodes, hash-consed construction with constants folded, trigonometric
//! atoms from one `sin_cos` per joint, and the coefficients it can compute ([`Emit`]).

use std::collections::BTreeMap;

use num_traits::{One, Signed, Zero};

use crate::expr::{Expr, Monomial, Var};
use crate::poly::{Param, ParamMonomial, Poly};
use crate::ring::{to_f64, Rational};
use crate::trig::{Angle, Trig};

/// A node index.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub struct Id(pub u32);

/// A run-time input of a generated method (0-based joint index).
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub enum Input {
    /// Joint angle.
    Q(usize),
    /// Joint rate.
    Qd(usize),
    /// Joint acceleration.
    Qdd(usize),
    /// Joint torque.
    Tau(usize),
    /// A virtual rate of joint `j`: a direction to differentiate along that no value reads
    /// (the regressor's rows are the virtual power's derivatives along these; see
    /// `programs::spatial_regressor`).
    Virtual(usize),
    /// Component 0 (x) or 1 (y) of a tip force.
    Force(usize),
    /// Torque applied at the tip.
    TipTorque,
    /// A run-time parameter, by its index in [`Program::params`], read from the arm's field.
    Param(usize),
    /// Slot `k` of a block of parameter-only values evaluated beforehand (see
    /// [`frozen`](crate::frozen)).
    Frozen(usize),
}

/// The most bits (numerator and denominator together) a folded constant keeps exactly. Named
/// constants (the cosine of a twist of 0.3 rad) enter as the exact value of their `f64`, with a
/// 2^52 denominator; folding products of twenty of them would carry thousand-bit integers
/// through every later fold and hash for no digit the emitted `f64` keeps.
const CONSTANT_BITS: u64 = 256;

/// A node of a straight-line program.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Debug)]
pub enum Node {
    /// An input.
    Input(Input),
    /// An exact constant, emitted as `num / den` in `f64`.
    Const(Rational),
    /// `sin q_j` (joint `j`'s one sine-cosine pair).
    Sin(usize),
    /// `cos q_j`.
    Cos(usize),
    /// Sum.
    Add(Id, Id),
    /// Difference.
    Sub(Id, Id),
    /// Product.
    Mul(Id, Id),
    /// Quotient.
    Div(Id, Id),
    /// Negation.
    Neg(Id),
    /// The larger of two values, `a.max(b)`: keeps a pivot above its rounding noise.
    Max(Id, Id),
    /// The sign of `a`: -1, 0 or 1 (0 at zero, unlike `f64::signum`; NaN stays NaN).
    Sign(Id),
}

/// A hash-consed straight-line program.
#[derive(Clone, Debug, Default)]
pub struct Program {
    nodes: Vec<Node>,
    // Looked up, never iterated: ids follow insertion order, so a hash map keeps the output
    // deterministic while sparing the exact constants' comparisons of an ordered map.
    memo: rustc_hash::FxHashMap<Node, Id>,
    trig: BTreeMap<Angle, (Id, Id)>,
    names: BTreeMap<Id, String>,
    params: Vec<Param>,
}

impl Program {
    /// An empty program.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// The nodes, children before parents.
    #[must_use]
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }

    /// The node behind an id.
    #[must_use]
    pub fn node(&self, id: Id) -> &Node {
        &self.nodes[id.0 as usize]
    }

    /// A readable name given to a node (`c23` for `cos(q2 + q3)`), if any.
    #[must_use]
    pub fn name(&self, id: Id) -> Option<&str> {
        self.names.get(&id).map(String::as_str)
    }

    /// Gives a node a readable name (the first name given wins).
    pub fn set_name(&mut self, id: Id, name: String) {
        self.names.entry(id).or_insert(name);
    }

    pub(crate) fn intern(&mut self, node: Node) -> Id {
        if let Some(&id) = self.memo.get(&node) {
            return id;
        }
        let id = Id(u32::try_from(self.nodes.len()).expect("program exceeds u32 nodes"));
        self.nodes.push(node.clone());
        self.memo.insert(node, id);
        id
    }

    fn constant_value(&self, id: Id) -> Option<&Rational> {
        match self.node(id) {
            Node::Const(r) => Some(r),
            _ => None,
        }
    }

    /// An input.
    pub fn input(&mut self, input: Input) -> Id {
        self.intern(Node::Input(input))
    }

    /// An exact constant; one of more than `CONSTANT_BITS` (256) bits is rounded to the nearest
    /// `f64`, which is what the emitted code holds anyway.
    pub fn constant(&mut self, r: Rational) -> Id {
        let bits = r.numer().bits() + r.denom().bits();
        let r = match to_f64(&r).and_then(Rational::from_float) {
            Some(rounded) if bits > CONSTANT_BITS => rounded,
            _ => r,
        };
        self.intern(Node::Const(r))
    }

    /// The run-time parameters the program reads, in the order of [`Input::Param`] indices
    /// (first use).
    #[must_use]
    pub fn params(&self) -> &[Param] {
        &self.params
    }

    /// A run-time parameter.
    pub fn param(&mut self, param: &Param) -> Id {
        // A named constant is its value, which is a rational (every finite f64 is).
        if let Some(value) = param.value() {
            if let Some(r) = Rational::from_float(value) {
                return self.constant(r);
            }
        }
        let k = match self.params.iter().position(|p| p == param) {
            Some(k) => k,
            None => {
                self.params.push(param.clone());
                self.params.len() - 1
            }
        };
        self.input(Input::Param(k))
    }

    /// A coefficient: a constant, or a polynomial in run-time parameters.
    pub fn coefficient<C: Emit>(&mut self, c: &C) -> Id {
        c.node(self)
    }

    /// A polynomial in run-time parameters: its monomials' products are hash-consed, so a
    /// product of parameters used by several coefficients is computed once.
    pub fn poly(&mut self, poly: &Poly) -> Id {
        let mut terms = Vec::new();
        for (m, c) in poly.terms() {
            let mut acc: Option<Id> = None;
            for (param, e) in m.powers() {
                let x = self.param(param);
                for _ in 0..*e {
                    acc = Some(match acc {
                        Some(a) => self.mul(a, x),
                        None => x,
                    });
                }
            }
            let magnitude = self.constant(c.abs());
            let term = match acc {
                Some(a) => self.mul(magnitude, a),
                None => magnitude,
            };
            terms.push((c.is_negative(), term));
        }
        self.signed_sum(&terms)
    }

    /// `a + b`, folded and ordered so that `a + b` and `b + a` are one node.
    pub fn add(&mut self, a: Id, b: Id) -> Id {
        match (
            self.constant_value(a).cloned(),
            self.constant_value(b).cloned(),
        ) {
            (Some(x), Some(y)) => return self.constant(x + y),
            (Some(x), _) if x.is_zero() => return b,
            (_, Some(y)) if y.is_zero() => return a,
            _ => {}
        }
        if let Node::Neg(nb) = *self.node(b) {
            return self.sub(a, nb);
        }
        if let Node::Neg(na) = *self.node(a) {
            return self.sub(b, na);
        }
        let (a, b) = if a <= b { (a, b) } else { (b, a) };
        self.intern(Node::Add(a, b))
    }

    /// `a - b`, folded; `a - a` is 0 (the program computes exact algebra: a joint whose axis
    /// passes through the tool has no lever arm, whatever rounding would leave).
    pub fn sub(&mut self, a: Id, b: Id) -> Id {
        if a == b {
            return self.constant(Rational::zero());
        }
        match (
            self.constant_value(a).cloned(),
            self.constant_value(b).cloned(),
        ) {
            (Some(x), Some(y)) => return self.constant(x - y),
            (_, Some(y)) if y.is_zero() => return a,
            (Some(x), _) if x.is_zero() => return self.neg(b),
            _ => {}
        }
        if let Node::Neg(nb) = *self.node(b) {
            return self.add(a, nb);
        }
        self.intern(Node::Sub(a, b))
    }

    /// `a b`, folded and ordered.
    pub fn mul(&mut self, a: Id, b: Id) -> Id {
        match (
            self.constant_value(a).cloned(),
            self.constant_value(b).cloned(),
        ) {
            (Some(x), Some(y)) => return self.constant(x * y),
            (Some(x), _) | (_, Some(x)) if x.is_zero() => return self.constant(Rational::zero()),
            (Some(x), _) if x.is_one() => return b,
            (_, Some(y)) if y.is_one() => return a,
            (Some(x), _) if (-x.clone()).is_one() => return self.neg(b),
            (_, Some(y)) if (-y.clone()).is_one() => return self.neg(a),
            _ => {}
        }
        // Constants first, so products read `(1.0 / 2.0) * c2`.
        let a_const = self.constant_value(a).is_some();
        let b_const = self.constant_value(b).is_some();
        let (a, b) = if (b_const && !a_const) || (a_const == b_const && b < a) {
            (b, a)
        } else {
            (a, b)
        };
        self.intern(Node::Mul(a, b))
    }

    /// `a / b`.
    pub fn div(&mut self, a: Id, b: Id) -> Id {
        if let Some(y) = self.constant_value(b) {
            if y.is_one() {
                return a;
            }
        }
        self.intern(Node::Div(a, b))
    }

    /// `a.max(b)`.
    pub fn max(&mut self, a: Id, b: Id) -> Id {
        self.intern(Node::Max(a, b))
    }

    /// The sign of `a` (0 at zero).
    pub fn sign(&mut self, a: Id) -> Id {
        if let Some(x) = self.constant_value(a).cloned() {
            return self.constant(x.signum());
        }
        self.intern(Node::Sign(a))
    }

    /// `-a`, folded.
    pub fn neg(&mut self, a: Id) -> Id {
        if let Some(x) = self.constant_value(a).cloned() {
            return self.constant(-x);
        }
        if let Node::Neg(inner) = *self.node(a) {
            return inner;
        }
        self.intern(Node::Neg(a))
    }

    /// `(cos angle, sin angle)`, built by angle addition from per-joint `sin_cos`.
    pub fn trig_pair(&mut self, angle: &Angle) -> (Id, Id) {
        if angle.is_zero() {
            let one = self.constant(Rational::one());
            let zero = self.constant(Rational::zero());
            return (one, zero);
        }
        if let Some(&pair) = self.trig.get(angle) {
            return pair;
        }
        let k = angle.coefficients();
        let j = k.len() - 1;
        let kj = k[j];
        let step = kj.signum();
        let mut rest = k.to_vec();
        rest[j] -= step;
        let (c0, s0) = self.trig_pair(&Angle::new(rest));
        let cj = self.intern(Node::Cos(j));
        let sj = self.intern(Node::Sin(j));
        let cc = self.mul(c0, cj);
        let ss = self.mul(s0, sj);
        let sc = self.mul(s0, cj);
        let cs = self.mul(c0, sj);
        let (c, s) = if step > 0 {
            // cos(a + b) = ca cb - sa sb, sin(a + b) = sa cb + ca sb
            (self.sub(cc, ss), self.add(sc, cs))
        } else {
            // cos(a - b) = ca cb + sa sb, sin(a - b) = sa cb - ca sb
            (self.add(cc, ss), self.sub(sc, cs))
        };
        let frag = angle.ident_fragment();
        self.set_name(c, format!("c{frag}"));
        self.set_name(s, format!("s{frag}"));
        self.trig.insert(angle.clone(), (c, s));
        (c, s)
    }

    /// The trigonometric atoms built so far by [`trig_pair`](Self::trig_pair): each angle
    /// with its `(cos, sin)` nodes.
    pub fn trig_atoms(&self) -> impl Iterator<Item = (&Angle, (Id, Id))> {
        self.trig.iter().map(|(a, &pair)| (a, pair))
    }

    /// The value of a trig atom.
    pub fn atom(&mut self, t: &Trig) -> Id {
        match t {
            Trig::One => self.constant(Rational::one()),
            Trig::Cos(a) => self.trig_pair(a).0,
            Trig::Sin(a) => self.trig_pair(a).1,
        }
    }

    /// The value of a monomial in rates and accelerations.
    pub fn monomial(&mut self, m: &Monomial) -> Id {
        let mut acc = self.constant(Rational::one());
        for (v, e) in m.powers() {
            let x = match v {
                Var::Qd(j) => self.input(Input::Qd(j)),
                Var::Qdd(j) => self.input(Input::Qdd(j)),
                Var::Q(j) => self.input(Input::Q(j)),
            };
            for _ in 0..e {
                acc = self.mul(acc, x);
            }
        }
        acc
    }

    /// `sum_k (sign_k x_k)`: the positive terms summed as a balanced tree, minus the negative
    /// ones summed likewise, so that the chain of dependent additions grows like `log2` of the
    /// number of terms, not linearly (a long sum is latency-bound otherwise).
    pub fn signed_sum(&mut self, terms: &[(bool, Id)]) -> Id {
        let positive: Vec<Id> = terms.iter().filter(|t| !t.0).map(|t| t.1).collect();
        let negative: Vec<Id> = terms.iter().filter(|t| t.0).map(|t| t.1).collect();
        match (self.balanced_sum(&positive), self.balanced_sum(&negative)) {
            (Some(p), Some(n)) => self.sub(p, n),
            (Some(p), None) => p,
            // All negative: `-a - (b + c + ...)` reads better than `-(a + b + c + ...)`.
            (None, Some(_)) => {
                let first = self.neg(negative[0]);
                match self.balanced_sum(&negative[1..]) {
                    Some(rest) => self.sub(first, rest),
                    None => first,
                }
            }
            (None, None) => self.constant(Rational::zero()),
        }
    }

    /// `x_0 + x_1 + ...` as a balanced tree of additions (halves, in order), or `None` if empty.
    pub fn balanced_sum(&mut self, terms: &[Id]) -> Option<Id> {
        match terms {
            [] => None,
            [x] => Some(*x),
            _ => {
                let (left, right) = terms.split_at(terms.len().div_ceil(2));
                let l = self.balanced_sum(left)?;
                let r = self.balanced_sum(right)?;
                Some(self.add(l, r))
            }
        }
    }

    /// The value of an exact expression: `sum over monomials m of m x (sum c_t atom_t)`,
    /// factoring each monomial out of its trig polynomial.
    pub fn expr<C: Emit>(&mut self, e: &Expr<C>) -> Id {
        let mut groups: BTreeMap<&Monomial, Vec<(&Trig, &C)>> = BTreeMap::new();
        for (m, t, c) in e.terms() {
            groups.entry(m).or_default().push((t, c));
        }
        let mut outer = Vec::new();
        for (m, terms) in groups {
            let mut inner = Vec::new();
            for (t, c) in terms {
                let atom = self.atom(t);
                let (negative, magnitude) = c.sign_split();
                let magnitude = magnitude.node(self);
                inner.push((negative, self.mul(magnitude, atom)));
            }
            // A single negative term keeps its sign outside, to multiply the monomial once.
            let (neg, poly) = if inner.len() == 1 {
                inner[0]
            } else {
                (false, self.signed_sum(&inner))
            };
            let mono = self.monomial(m);
            outer.push((neg, self.mul(poly, mono)));
        }
        self.signed_sum(&outer)
    }

    /// Copies the part of `other` that `roots` need into this program, each input of `other`
    /// replaced by the node `input` gives for it (or taken as the same input when it gives
    /// `None`; parameters are matched by name); returns the roots' nodes here. The copies are
    /// rebuilt with the folding constructors, so they share every node this program already
    /// has and fold what the substitution makes constant.
    pub fn graft(
        &mut self,
        other: &Program,
        roots: &[Id],
        input: &dyn Fn(Input) -> Option<Id>,
    ) -> Vec<Id> {
        let uses = other.use_counts(roots);
        let mut map: Vec<Option<Id>> = vec![None; other.nodes.len()];
        for (i, node) in other.nodes.iter().enumerate() {
            if uses[i] == 0 {
                continue;
            }
            let at = |x: Id| map[x.0 as usize].expect("children come first");
            let id = match *node {
                Node::Input(Input::Param(k)) => self.param(&other.params[k]),
                Node::Input(i) => input(i).unwrap_or_else(|| self.input(i)),
                Node::Const(ref r) => self.constant(r.clone()),
                Node::Sin(_) | Node::Cos(_) => self.intern(node.clone()),
                Node::Add(a, b) => self.add(at(a), at(b)),
                Node::Sub(a, b) => self.sub(at(a), at(b)),
                Node::Mul(a, b) => self.mul(at(a), at(b)),
                Node::Div(a, b) => self.div(at(a), at(b)),
                Node::Neg(a) => self.neg(at(a)),
                Node::Max(a, b) => self.max(at(a), at(b)),
                Node::Sign(a) => self.sign(at(a)),
            };
            map[i] = Some(id);
        }
        for (&from, name) in &other.names {
            if let Some(to) = map[from.0 as usize] {
                self.set_name(to, name.clone());
            }
        }
        for (angle, &(c, s)) in &other.trig {
            if let (Some(c), Some(s)) = (map[c.0 as usize], map[s.0 as usize]) {
                self.trig.entry(angle.clone()).or_insert((c, s));
            }
        }
        roots
            .iter()
            .map(|r| map[r.0 as usize].expect("roots are live"))
            .collect()
    }
}

/// The operands of a node.
#[must_use]
pub fn children(node: &Node) -> Vec<Id> {
    match *node {
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) | Node::Max(a, b) => {
            vec![a, b]
        }
        Node::Neg(a) | Node::Sign(a) => vec![a],
        Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_) => vec![],
    }
}

/// A coefficient the programs can compute: an exact constant ([`Rational`]) or a polynomial in
/// run-time parameters ([`Poly`]).
pub trait Emit: crate::ring::Coefficient {
    /// The node that computes the coefficient.
    fn node(&self, p: &mut Program) -> Id;
    /// The exact value, when it involves no parameter.
    fn rational(&self) -> Option<Rational>;
    /// `(negative, magnitude)`, the sign pulled out where it is known (a constant, or a
    /// polynomial whose coefficients are all negative), so that `a - b` is emitted instead of
    /// `a + (-b)`.
    fn sign_split(&self) -> (bool, Self);
    /// The terms: each product of parameters with its rational coefficient (one term with no
    /// parameter for a constant; none for zero).
    fn parts(&self) -> Vec<(ParamMonomial, Rational)>;
    /// How many [`parts`](Self::parts), without building them.
    fn part_count(&self) -> usize {
        self.parts().len()
    }
}

impl Emit for Rational {
    fn node(&self, p: &mut Program) -> Id {
        p.constant(self.clone())
    }
    fn rational(&self) -> Option<Rational> {
        Some(self.clone())
    }
    fn sign_split(&self) -> (bool, Self) {
        (self.is_negative(), self.abs())
    }
    fn parts(&self) -> Vec<(ParamMonomial, Rational)> {
        if Zero::is_zero(self) {
            Vec::new()
        } else {
            vec![(ParamMonomial::default(), self.clone())]
        }
    }
    fn part_count(&self) -> usize {
        usize::from(!Zero::is_zero(self))
    }
}

impl Emit for Poly {
    fn node(&self, p: &mut Program) -> Id {
        p.poly(self)
    }
    fn rational(&self) -> Option<Rational> {
        self.as_rational()
    }
    fn sign_split(&self) -> (bool, Self) {
        let negative =
            !crate::ring::Coefficient::is_zero(self) && self.terms().all(|(_, c)| c.is_negative());
        if negative {
            (true, -self.clone())
        } else {
            (false, self.clone())
        }
    }
    fn parts(&self) -> Vec<(ParamMonomial, Rational)> {
        self.terms().map(|(m, c)| (m.clone(), c.clone())).collect()
    }
    fn part_count(&self) -> usize {
        self.terms().count()
    }
}
