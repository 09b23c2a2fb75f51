//! Identification: the regressor and the base parameters, derived exactly.

pub mod regressor;
