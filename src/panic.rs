//! The panic handler of the `core`-only build (`--no-default-features`).
//!
//! No export can reach it: `c_tests/no_panic.sh` links every export under the `no-panic`
//! proof. It exists because a `no_std` library linked into a C program must name one. If it
//! were ever reached, a trap instruction hands control to the controller's exception handling
//! (a defined machine stop) instead of returning garbage or needing `abort()` from a C library
//! that a real-time target may not have.

#[cfg(all(not(feature = "std"), not(test)))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo) -> ! {
    trap()
}

// SAFETY (all three): the instruction only raises the architecture's undefined-instruction or
// breakpoint trap; it touches no memory.
#[cfg(all(
    not(feature = "std"),
    not(test),
    any(target_arch = "x86", target_arch = "x86_64")
))]
fn trap() -> ! {
    unsafe { core::arch::asm!("ud2", options(nomem, nostack, noreturn)) }
}

#[cfg(all(not(feature = "std"), not(test), target_arch = "aarch64"))]
fn trap() -> ! {
    unsafe { core::arch::asm!("brk #0xc0de", options(nomem, nostack, noreturn)) }
}

#[cfg(all(not(feature = "std"), not(test), target_arch = "arm"))]
fn trap() -> ! {
    unsafe { core::arch::asm!("udf #0", options(nomem, nostack, noreturn)) }
}

/// Other architectures spin until the controller's watchdog stops the machine.
#[cfg(all(
    not(feature = "std"),
    not(test),
    not(any(
        target_arch = "x86",
        target_arch = "x86_64",
        target_arch = "aarch64",
        target_arch = "arm"
    ))
))]
fn trap() -> ! {
    loop {
        core::hint::spin_loop()
    }
}

// The precompiled `core` carries unwind tables that name `rust_eh_personality` even when the
// crate is built with `panic = "abort"`: without a definition, linking the `core`-only library
// into a C program fails on that symbol. Nothing unwinds, so nothing calls it. It is defined in
// assembly, not as a Rust `#[no_mangle]` function, because Rust exports those from a shared
// library, and the library must export nothing but `cncrot_*`: on ELF targets the symbol is
// hidden; on Windows a plain global label, which the DLL's export list (written by rustc from
// the Rust exports) does not name. Elsewhere it is a plain Rust function.
#[cfg(all(not(feature = "std"), not(test)))]
mod personality {
    #[cfg(all(
        not(any(target_os = "windows", target_vendor = "apple")),
        any(
            target_arch = "x86",
            target_arch = "x86_64",
            target_arch = "aarch64",
            target_arch = "arm"
        )
    ))]
    macro_rules! hidden_empty_function {
        ($ret:literal) => {
            core::arch::global_asm!(
                ".pushsection .text.rust_eh_personality,\"ax\"",
                ".globl rust_eh_personality",
                ".hidden rust_eh_personality",
                ".type rust_eh_personality, %function",
                "rust_eh_personality:",
                $ret,
                ".size rust_eh_personality, . - rust_eh_personality",
                ".popsection",
            );
        };
    }

    #[cfg(all(
        not(any(target_os = "windows", target_vendor = "apple")),
        any(target_arch = "x86", target_arch = "x86_64", target_arch = "aarch64")
    ))]
    hidden_empty_function!("ret");

    #[cfg(all(
        not(any(target_os = "windows", target_vendor = "apple")),
        target_arch = "arm"
    ))]
    hidden_empty_function!("bx lr");

    // COFF: no symbol visibility; an undecorated name on 64-bit targets.
    #[cfg(all(
        target_os = "windows",
        any(target_arch = "x86_64", target_arch = "aarch64")
    ))]
    core::arch::global_asm!(
        ".text",
        ".globl rust_eh_personality",
        "rust_eh_personality:",
        "ret",
    );

    #[cfg(not(any(
        all(
            not(any(target_os = "windows", target_vendor = "apple")),
            any(
                target_arch = "x86",
                target_arch = "x86_64",
                target_arch = "aarch64",
                target_arch = "arm"
            )
        ),
        all(
            target_os = "windows",
            any(target_arch = "x86_64", target_arch = "aarch64")
        )
    )))]
    #[no_mangle]
    extern "C" fn rust_eh_personality() {}
}
