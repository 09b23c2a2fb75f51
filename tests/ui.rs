//! Compile-time diagnostics of `#[derive(PlanarArm)]` and `#[derive(SpatialArm)]` (`spatial/`)
//! (one bad input per file, with the compiler's output checked in next to it) and valid edge
//! inputs that must compile and run.
//!
//! Re-bless the `.stderr` files with `TRYBUILD=overwrite cargo test --test ui`, then read them.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/shape/*.rs");
    t.compile_fail("tests/ui/attr/*.rs");
    t.compile_fail("tests/ui/value/*.rs");
    t.compile_fail("tests/ui/physics/*.rs");
    t.compile_fail("tests/ui/param/*.rs");
    t.compile_fail("tests/ui/range/*.rs");
    t.compile_fail("tests/ui/stub/*.rs");
    t.compile_fail("tests/ui/spatial/*.rs");
    t.pass("tests/ui/pass/*.rs");
}
