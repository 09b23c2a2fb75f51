//! A generated method's body as a program: the program, its named outputs, and how it
//! evaluates the method.

use crate::slp::{Id, Input, OpCount, Program};

/// One generated method body: its program, the outputs, and how to name them.
#[derive(Clone, Debug)]
pub struct Method {
    /// The program.
    pub program: Program,
    /// The output nodes with the names of their `let`s.
    pub outputs: Vec<(String, Id)>,
    /// How the program evaluates the method, for its doc comment (empty when it evaluates the
    /// documented formulas term by term).
    pub evaluation: String,
    /// The same outputs as derivatives computed four directions at a time, which the method
    /// emits instead of `program` (see [`crate::packed`]).
    pub packed: Option<Box<crate::programs::packed::Packed>>,
}

impl Method {
    /// The outputs evaluated by the program interpreter (see [`Program::eval`]).
    #[must_use]
    pub fn eval(&self, input: &dyn Fn(Input) -> f64) -> Vec<f64> {
        let values = self.program.eval(input);
        self.outputs
            .iter()
            .map(|(_, id)| values[id.0 as usize])
            .collect()
    }

    /// The operation count of this method.
    #[must_use]
    pub fn op_count(&self) -> OpCount {
        let outs: Vec<Id> = self.outputs.iter().map(|o| o.1).collect();
        self.program.op_count(&outs)
    }

    /// The longest chain of dependent operations to an output (see [`Program::depth`]).
    #[must_use]
    pub fn depth(&self) -> usize {
        let outs: Vec<Id> = self.outputs.iter().map(|o| o.1).collect();
        self.program.depth(&outs)
    }

    pub(crate) fn new(program: Program, outputs: Vec<(String, Id)>) -> Self {
        Self {
            program,
            outputs,
            evaluation: String::new(),
            packed: None,
        }
    }

    pub(crate) fn described(mut self, evaluation: &str) -> Self {
        self.evaluation = evaluation.to_string();
        self
    }
}

/// The 1-based suffix `12` of entry `(i, j)`, in the names of matrix entries (`m12`, `l12`).
pub(crate) fn two(i: usize, j: usize) -> String {
    format!("{}{}", i + 1, j + 1)
}
