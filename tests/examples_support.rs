//! What the examples share: where their pictures go (never `docs/` unless asked, so that running
//! an example leaves the repository as it was) and how they print numbers. Compiled here from
//! the examples' own files, so that `cargo test` runs their tests too.

#[path = "../examples/support/num.rs"]
mod num;
#[allow(dead_code)]
#[path = "../examples/support/out.rs"]
mod out;

use std::path::Path;

use out::Out;

fn dir(args: &[&str]) -> Result<Option<std::path::PathBuf>, String> {
    Out::directory(args.iter().map(|s| (*s).to_string()))
}

#[test]
fn pictures_go_to_the_target_directory_unless_docs_is_asked_for() {
    let docs = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs");
    let default = dir(&[]).unwrap().unwrap();
    assert!(!default.starts_with(&docs), "{}", default.display());
    assert!(default.ends_with("pictures"), "{}", default.display());
    assert_eq!(dir(&["--docs"]).unwrap().unwrap(), docs);
    assert_eq!(
        dir(&["--out", "/tmp/x"]).unwrap().unwrap(),
        Path::new("/tmp/x")
    );
    assert_eq!(dir(&["--help"]).unwrap(), None);
    for bad in [&["--out"][..], &["--docs", "--out", "x"], &["--pictures"]] {
        assert!(dir(bad).is_err(), "{bad:?}");
    }
}
