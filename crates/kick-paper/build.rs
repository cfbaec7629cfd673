//! The build this binary was made with, for the timing page (`kick bench`):
//! the compiler, the profile and its settings, the target and its
//! features, and RUSTFLAGS, as `KICK_BUILD`.

fn main() {
    let env = |name: &str| std::env::var(name).unwrap_or_default();
    let rustc = std::process::Command::new(std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into()))
        .arg("--version")
        .output()
        .ok()
        .and_then(|o| String::from_utf8(o.stdout).ok())
        .map(|v| v.trim().to_string())
        .unwrap_or_else(|| "rustc (version unknown)".into());
    let profile = env("PROFILE");
    // The workspace's [profile.NAME] settings (lto, codegen-units, ...), which build scripts are not told.
    let manifest = std::path::Path::new(&env("CARGO_MANIFEST_DIR")).join("../../Cargo.toml");
    println!("cargo:rerun-if-changed={}", manifest.display());
    println!("cargo:rerun-if-changed=build.rs");
    let settings: Vec<String> = std::fs::read_to_string(&manifest)
        .map(|text| {
            let header = format!("[profile.{profile}]");
            text.lines()
                .skip_while(|l| l.trim() != header)
                .skip(1)
                .take_while(|l| !l.trim_start().starts_with('['))
                .map(|l| l.split('#').next().unwrap_or("").trim().to_string())
                .filter(|l| !l.is_empty())
                .collect()
        })
        .unwrap_or_default();
    let rustflags = env("CARGO_ENCODED_RUSTFLAGS").replace('\x1f', " ");
    let build = format!(
        "{rustc}; profile {profile} (opt-level {}, debug {}{}); target {} (features {}); RUSTFLAGS {}",
        env("OPT_LEVEL"),
        env("DEBUG"),
        if settings.is_empty() { String::new() } else { format!(", {}", settings.join(", ")) },
        env("TARGET"),
        env("CARGO_CFG_TARGET_FEATURE"),
        if rustflags.trim().is_empty() { "none".to_string() } else { format!("`{}`", rustflags.trim()) },
    );
    println!("cargo:rerun-if-env-changed=RUSTFLAGS");
    println!("cargo:rerun-if-env-changed=CARGO_ENCODED_RUSTFLAGS");
    println!("cargo:rustc-env=KICK_BUILD={build}");
}
