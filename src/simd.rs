//! Batches of states in SIMD lanes: simba's `wide`-backed scalar types, which implement
//! [`Real`](crate::Real), and the [`SimdValue`] trait that builds and reads their lanes
//! (`WideF64x4::from([..; 4])`, `x.extract(lane)`, `WideF64x4::splat(x)`).
//!
//! A batch type holds one state per lane: `SVector<WideF64x4, N>` is four states, and the
//! generated dynamics evaluate all four in one call. docs/performance.md measures what that
//! buys against as many scalar calls.

pub use simba::simd::{SimdValue, WideF32x4, WideF32x8, WideF64x4};
