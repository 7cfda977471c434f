//! Generates the C header `include/cncrot.h` with cbindgen.
//!
//! The header is always written to `$OUT_DIR/cncrot.h`. The committed copy in `include/` is
//! refreshed too, unless `CNCROT_FROZEN_HEADER` is set: the test command sets it, so that a
//! committed header that no longer matches the sources fails the `header_is_fresh` test
//! instead of being silently rewritten.

use std::path::PathBuf;

fn main() {
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=cbindgen.toml");
    println!("cargo:rerun-if-env-changed=CNCROT_FROZEN_HEADER");

    let crate_dir = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let out_dir = PathBuf::from(std::env::var("OUT_DIR").expect("set by cargo"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml"))
        .expect("cbindgen.toml is readable");
    let bindings = cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    bindings.write_to_file(out_dir.join("cncrot.h"));
    if std::env::var_os("CNCROT_FROZEN_HEADER").is_none() {
        bindings.write_to_file(crate_dir.join("include").join("cncrot.h"));
    }
}
