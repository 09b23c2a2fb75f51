//! The parameter-only part of methods, evaluated once per parameter change.
//!
//! An arm whose values are run-time parameters computes, inside every call, products and sums
//! of parameters that do not depend on the state (`i3 + m3 c3^2`, `m2 + m3`, ...). Split at
//! the boundary where such a value meets a state-dependent one, a method becomes two
//! programs: a *block* that evaluates the parameter-only values at the boundary (the frontier)
//! from the arm's fields, and the method itself reading them as inputs
//! ([`Input::Frozen`]). The block is shared by several methods, with common values computed
//! once. The facade's `Frozen` view holds the block next to a shared borrow of the arm, so the
//! parameters cannot change while the block is in use.

use std::collections::BTreeMap;

use super::method::Method;
use crate::slp::{children, Id, Input, Node, Program};

/// Methods split at their parameter-only frontier.
#[derive(Clone, Debug)]
pub struct Frozen {
    /// Evaluates every slot of the block from the parameters; output `k` is slot `k`.
    pub block: Method,
    /// The methods, in the order given, reading their parameter-only values from the block.
    pub methods: Vec<Method>,
}

/// Splits `methods` at their parameter-only frontier, or `None` when no method has a
/// parameter-only operation (every all-literal arm: its constants are folded already).
#[must_use]
pub fn freeze(methods: &[Method]) -> Option<Frozen> {
    let mut block = Program::new();
    let mut slots: Vec<Id> = Vec::new();
    let mut slot_of: BTreeMap<Id, usize> = BTreeMap::new();
    let mut names: Vec<String> = Vec::new();
    let mut split = Vec::new();
    for m in methods {
        let p = &m.program;
        let outs: Vec<Id> = m.outputs.iter().map(|o| o.1).collect();
        let frontier = frontier(p, &outs);
        let mut memo = BTreeMap::new();
        let mut local_slot = BTreeMap::new();
        for &f in &frontier {
            let b = import(&mut block, p, f, &mut memo);
            let k = *slot_of.entry(b).or_insert_with(|| {
                slots.push(b);
                names.push(
                    p.name(f)
                        .map_or_else(|| format!("frozen{}", slots.len() - 1), str::to_string),
                );
                slots.len() - 1
            });
            local_slot.insert(f, k);
        }
        split.push(rebuild(m, &local_slot));
    }
    if slots.is_empty() {
        return None;
    }
    let outputs = names.into_iter().zip(slots).collect();
    Some(Frozen {
        block: Method {
            program: block,
            outputs,
            evaluation: String::new(),
            packed: None,
        },
        methods: split,
    })
}

/// The parameter-only operations that a state-dependent operation or an output reads.
fn frontier(p: &Program, outputs: &[Id]) -> Vec<Id> {
    let uses = p.use_counts(outputs);
    let nodes = p.nodes();
    let mut pure = vec![false; nodes.len()];
    for (i, node) in nodes.iter().enumerate() {
        pure[i] = match node {
            Node::Input(Input::Param(_) | Input::Frozen(_)) | Node::Const(_) => true,
            Node::Input(_) | Node::Sin(_) | Node::Cos(_) => false,
            _ => children(node).iter().all(|c| pure[c.0 as usize]),
        };
    }
    let is_operation = |i: usize| pure[i] && !matches!(nodes[i], Node::Input(_) | Node::Const(_));
    let mut frontier = std::collections::BTreeSet::new();
    for &o in outputs {
        if is_operation(o.0 as usize) {
            frontier.insert(o);
        }
    }
    for (i, node) in nodes.iter().enumerate() {
        if uses[i] == 0 || pure[i] {
            continue;
        }
        for c in children(node) {
            if is_operation(c.0 as usize) {
                frontier.insert(c);
            }
        }
    }
    frontier.into_iter().collect()
}

/// Copies node `id` of `from`, with what it reads, into `to`; `memo` maps `from`'s ids.
fn import(to: &mut Program, from: &Program, id: Id, memo: &mut BTreeMap<Id, Id>) -> Id {
    // Children come before parents, so one pass over the needed ids in order suffices.
    let mut needed = std::collections::BTreeSet::new();
    let mut stack = vec![id];
    while let Some(i) = stack.pop() {
        if memo.contains_key(&i) || !needed.insert(i) {
            continue;
        }
        stack.extend(children(from.node(i)));
    }
    for i in needed {
        let node = match from.node(i) {
            Node::Input(Input::Param(k)) => {
                let new = to.param(&from.params()[*k]);
                memo.insert(i, new);
                continue;
            }
            other => map_children(other, memo),
        };
        let new = to.intern(node);
        if let Some(name) = from.name(i) {
            to.set_name(new, name.to_string());
        }
        memo.insert(i, new);
    }
    memo[&id]
}

/// The method with each frontier node replaced by its block slot.
fn rebuild(m: &Method, slot: &BTreeMap<Id, usize>) -> Method {
    let from = &m.program;
    let mut to = Program::new();
    let mut memo: BTreeMap<Id, Id> = BTreeMap::new();
    let mut needed = std::collections::BTreeSet::new();
    let mut stack: Vec<Id> = m.outputs.iter().map(|o| o.1).collect();
    while let Some(i) = stack.pop() {
        if !needed.insert(i) || slot.contains_key(&i) {
            continue;
        }
        stack.extend(children(from.node(i)));
    }
    for i in needed {
        let new = if let Some(&k) = slot.get(&i) {
            to.input(Input::Frozen(k))
        } else if let Node::Input(Input::Param(k)) = from.node(i) {
            to.param(&from.params()[*k])
        } else {
            let node = map_children(from.node(i), &memo);
            let new = to.intern(node);
            if let Some(name) = from.name(i) {
                to.set_name(new, name.to_string());
            }
            new
        };
        memo.insert(i, new);
    }
    Method {
        program: to,
        outputs: m
            .outputs
            .iter()
            .map(|(name, id)| (name.clone(), memo[id]))
            .collect(),
        evaluation: m.evaluation.clone(),
        packed: None,
    }
}

fn map_children(node: &Node, memo: &BTreeMap<Id, Id>) -> Node {
    let m = |c: &Id| memo[c];
    match node {
        Node::Add(a, b) => Node::Add(m(a), m(b)),
        Node::Sub(a, b) => Node::Sub(m(a), m(b)),
        Node::Mul(a, b) => Node::Mul(m(a), m(b)),
        Node::Div(a, b) => Node::Div(m(a), m(b)),
        Node::Max(a, b) => Node::Max(m(a), m(b)),
        Node::Neg(a) => Node::Neg(m(a)),
        Node::Sign(a) => Node::Sign(m(a)),
        leaf @ (Node::Input(_) | Node::Const(_) | Node::Sin(_) | Node::Cos(_)) => leaf.clone(),
    }
}
