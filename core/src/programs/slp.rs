//! Straight-line programs: the run-time half of the engine.
//!
//! A [`Program`] is an arena of nodes addressed by [`Id`], children before parents (egg's
//! `RecExpr`). Construction is hash-consed, so a subexpression built twice is one node and
//! common subexpressions are shared by construction. Trigonometric atoms are built from one
//! `sin_cos` per joint by the angle-addition formulas, each computed once per call.

mod analysis;
mod program;

pub use analysis::{sign, OpCount, DIV_LATENCY};
pub use program::{children, Emit, Id, Input, Node, Program};
