//! README.md's Rust blocks are complete programs: each has its own `fn main`, so that one pasted
//! into `src/main.rs` compiles as it is (the crate page runs them all as doctests, which would
//! wrap a bare block in a `main` of its own and hide a missing one).

#[test]
fn every_rust_block_of_the_readme_has_a_main() {
    let readme = include_str!("../README.md");
    let mut blocks = 0;
    let mut rest = readme;
    while let Some(start) = rest.find("```rust") {
        let body = &rest[start + "```rust".len()..];
        let end = body.find("```").expect("every block is closed");
        let block = &body[..end];
        assert!(
            block.contains("\nfn main()"),
            "a README block without `fn main()`:\n{block}"
        );
        blocks += 1;
        rest = &body[end + 3..];
    }
    assert!(blocks >= 6, "{blocks} Rust blocks");
}
