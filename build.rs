//! Gives the shared library its soname, so that programs linked against it find the
//! installed library by its ABI version (`libcncrot.so.0.2` for 0.2.z, `libcncrot.so.N` for
//! N.y.z: Cargo's semver-compatibility rule, the one cargo-c follows).
//!
//! The C header is not generated here: `tests/header.rs` generates it with cbindgen and
//! fails when the committed `include/cncrot.h` differs (`CNCROT_BLESS=1` rewrites it), so a
//! build of the library needs no build dependency.

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let family = std::env::var("CARGO_CFG_TARGET_FAMILY").unwrap_or_default();
    let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_default();
    let minor = std::env::var("CARGO_PKG_VERSION_MINOR").unwrap_or_default();
    let abi = if major == "0" {
        format!("0.{minor}")
    } else {
        major
    };
    // ELF platforms; Apple platforms use install names and Windows import libraries.
    if family == "unix" && !matches!(os.as_str(), "macos" | "ios") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libcncrot.so.{abi}");
    }
}
