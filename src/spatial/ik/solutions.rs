//! [`IkSolutions`]: at most eight joint vectors, held without allocation.

use core::ops::Deref;

use nalgebra::SVector;

/// The solutions of a closed-form inverse kinematics, at most eight, in a fixed array (no
/// allocation). Dereferences to `[SVector<f64, N>]`.
///
/// [`singular`](Self::singular) says whether the target lies on a singularity, where the
/// solutions form continuous families; each family is then represented by one member, as the
/// solver's documentation says which.
///
/// # Example
/// ```
/// use planar_arm::spatial::IkSolutions;
/// use planar_arm::nalgebra::SVector;
///
/// let mut s = IkSolutions::<2>::new();
/// s.push(SVector::from([0.1, 0.2]));
/// assert_eq!(s.len(), 1);
/// assert_eq!(s[0][1], 0.2);
/// assert!(!s.singular());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IkSolutions<const N: usize> {
    solutions: [SVector<f64, N>; 8],
    len: usize,
    singular: bool,
}

impl<const N: usize> IkSolutions<N> {
    /// No solutions yet.
    #[must_use]
    pub fn new() -> Self {
        Self {
            solutions: [SVector::zeros(); 8],
            len: 0,
            singular: false,
        }
    }

    /// Adds a solution; the ninth and later are dropped (no arm of the supported classes has
    /// more than eight).
    pub fn push(&mut self, q: SVector<f64, N>) {
        if self.len < self.solutions.len() {
            self.solutions[self.len] = q;
            self.len += 1;
        }
    }

    /// Whether the target lies on a singularity (families of solutions, one member of each
    /// returned).
    #[must_use]
    pub fn singular(&self) -> bool {
        self.singular
    }

    /// Marks the solutions as representatives of families.
    pub fn mark_singular(&mut self) {
        self.singular = true;
    }

    /// The solutions, to change in place.
    pub(crate) fn as_mut_slice(&mut self) -> &mut [SVector<f64, N>] {
        &mut self.solutions[..self.len]
    }

    /// Keeps the first `len` solutions.
    pub(crate) fn truncate(&mut self, len: usize) {
        self.len = self.len.min(len);
    }
}

impl<const N: usize> Default for IkSolutions<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> Deref for IkSolutions<N> {
    type Target = [SVector<f64, N>];
    fn deref(&self) -> &Self::Target {
        &self.solutions[..self.len]
    }
}

impl<'a, const N: usize> IntoIterator for &'a IkSolutions<N> {
    type Item = &'a SVector<f64, N>;
    type IntoIter = core::slice::Iter<'a, SVector<f64, N>>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}
