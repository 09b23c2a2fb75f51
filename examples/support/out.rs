//! Where an example writes its pictures. By default under the target directory
//! (`target/pictures/`), so that running an example leaves the repository as it was;
//! `--out DIR` puts them in `DIR`; `--docs` refreshes the copies in `docs/` that README.md
//! shows. Included by the examples that draw (`#[path = "support/out.rs"] mod out;`).

use std::path::{Path, PathBuf};

/// The directory an example's pictures go to.
pub struct Out {
    dir: PathBuf,
}

impl Out {
    /// From the command line. `--help` prints the usage and exits; a wrong argument, or a
    /// directory that cannot be made, prints why and exits with status 2.
    pub fn from_args(example: &str) -> Self {
        let usage = format!(
            "usage: cargo run --release --example {example} [-- --out DIR | -- --docs]\n\
             \x20 (default) write the pictures to {}\n\
             \x20 --out DIR  write them to DIR\n\
             \x20 --docs     refresh the copies in docs/ that README.md shows",
            default_dir().display()
        );
        let fail = |why: &str| -> ! {
            eprintln!("error: {why}\n{usage}");
            std::process::exit(2)
        };
        let dir = match Self::directory(std::env::args().skip(1)) {
            Ok(Some(dir)) => dir,
            Ok(None) => {
                println!("{usage}");
                std::process::exit(0)
            }
            Err(why) => fail(&why),
        };
        if let Err(e) = std::fs::create_dir_all(&dir) {
            fail(&format!("cannot create {}: {e}", dir.display()));
        }
        Self { dir }
    }

    /// The directory the arguments choose, `None` for `--help`, or why they choose none.
    pub fn directory(args: impl IntoIterator<Item = String>) -> Result<Option<PathBuf>, String> {
        let mut dir = None;
        let mut args = args.into_iter();
        while let Some(arg) = args.next() {
            let chosen = match arg.as_str() {
                "--docs" => docs_dir(),
                "--out" => PathBuf::from(args.next().ok_or("--out needs a directory")?),
                "-h" | "--help" => return Ok(None),
                other => return Err(format!("unknown argument `{other}`")),
            };
            if dir.replace(chosen).is_some() {
                return Err("give one of --out and --docs, once".to_string());
            }
        }
        Ok(Some(dir.unwrap_or_else(default_dir)))
    }

    /// The path of the picture `name` (`"sim-energy.svg"`).
    pub fn path(&self, name: &str) -> PathBuf {
        self.dir.join(name)
    }

    /// Tells the user where a picture went.
    pub fn wrote(&self, path: &Path) {
        println!("wrote {}", path.display());
    }
}

/// `docs/` of this package: the pictures README.md shows.
fn docs_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs")
}

/// `pictures/` in the target directory this example was built in.
fn default_dir() -> PathBuf {
    target_dir().join("pictures")
}

/// The target directory: `CARGO_TARGET_DIR` if set (relative to the current directory, as
/// cargo reads it), else the directory above this executable that cargo marked as its own
/// (`CACHEDIR.TAG`; the executable is in `target/[triple/]profile/examples/`), else the
/// package's `target/`.
fn target_dir() -> PathBuf {
    if let Some(dir) = std::env::var_os("CARGO_TARGET_DIR").filter(|d| !d.is_empty()) {
        return PathBuf::from(dir);
    }
    std::env::current_exe()
        .ok()
        .and_then(|exe| {
            exe.ancestors()
                .skip(1)
                .find(|d| d.join("CACHEDIR.TAG").is_file())
                .map(Path::to_path_buf)
        })
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("target"))
}
