//! The workspace's shape, held by tests: no crate's top-level modules use
//! each other in a circle (issue 32: a module reads as a layer over the ones
//! it names, never as half of a knot).
//!
//! A module's uses are the `crate::NAME` paths in its files (`NAME.rs` and
//! `NAME/`), comments and `#[cfg(test)]` code left out: tests may reach
//! anywhere.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn crates() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates");
    let mut dirs: Vec<PathBuf> = std::fs::read_dir(&root).unwrap().map(|e| e.unwrap().path()).filter(|p| p.join("src").is_dir()).collect();
    dirs.sort();
    dirs
}

/// Source text without comments and without what follows `#[cfg(test)]`.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or("");
    text.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Identifiers following `crate::`, and inside `crate::{...}` groups.
fn crate_uses(code: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let ident = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
    for (i, _) in code.match_indices("crate::") {
        let rest = &code[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let inner = &group[..group.find('}').unwrap_or(group.len())];
            names.extend(inner.split(',').map(|part| ident(part.trim())));
        } else {
            names.insert(ident(rest));
        }
    }
    names.remove("");
    names
}

/// The top-level module graph of the crate at `dir`.
fn module_graph(dir: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let src = dir.join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let top = |p: &Path| -> String {
        let first = p.strip_prefix(&src).unwrap().components().next().unwrap().as_os_str().to_string_lossy().into_owned();
        first.trim_end_matches(".rs").to_string()
    };
    let modules: BTreeSet<String> = files.iter().map(|p| top(p)).filter(|m| m != "lib" && m != "main").collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> = modules.iter().map(|m| (m.clone(), BTreeSet::new())).collect();
    for file in &files {
        let module = top(file);
        let Some(edges) = graph.get_mut(&module) else { continue };
        let used = crate_uses(&code(&std::fs::read_to_string(file).unwrap()));
        edges.extend(used.into_iter().filter(|u| modules.contains(u) && *u != module));
    }
    graph
}

/// The modules on a cycle (Tarjan's strongly connected components of more than one).
fn cycles(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        found: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let n = s.index.len();
        s.index.insert(v, n);
        s.low.insert(v, n);
        s.stack.push(v);
        for w in &s.graph[v] {
            let w = w.as_str();
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                s.low.entry(v).and_modify(|l| *l = (*l).min(lw));
            } else if s.stack.contains(&w) {
                let iw = s.index[w];
                s.low.entry(v).and_modify(|l| *l = (*l).min(iw));
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                component.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.found.push(component);
            }
        }
    }
    let mut s = State { graph, index: BTreeMap::new(), low: BTreeMap::new(), stack: Vec::new(), found: Vec::new() };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.found
}

#[test]
fn no_crate_has_modules_in_a_circle() {
    let mut knots = Vec::new();
    for dir in crates() {
        let graph = module_graph(&dir);
        for cycle in cycles(&graph) {
            let edges: Vec<String> =
                cycle.iter().map(|m| format!("{m} -> {:?}", graph[m].iter().filter(|u| cycle.contains(u)).collect::<Vec<_>>())).collect();
            knots.push(format!("{}: {}", dir.file_name().unwrap().to_string_lossy(), edges.join("; ")));
        }
    }
    assert!(knots.is_empty(), "modules in a circle:\n{}", knots.join("\n"));
}

/// The checker itself finds a circle, and finds none where there is none.
#[test]
fn the_circle_finder_finds_circles() {
    let graph = |edges: &[(&str, &str)]| {
        let mut g: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (a, b) in edges {
            g.entry(a.to_string()).or_default().insert(b.to_string());
            g.entry(b.to_string()).or_default();
        }
        g
    };
    assert_eq!(cycles(&graph(&[("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")])), vec![vec!["a", "b", "c"]]);
    assert!(cycles(&graph(&[("a", "b"), ("b", "c"), ("a", "c")])).is_empty());
    let uses = crate_uses(&code("use crate::{level::Failure, error};\nlet x = crate::flight::fly(); // crate::nothing\n"));
    assert_eq!(uses.into_iter().collect::<Vec<_>>(), ["error", "flight", "level"]);
}

/// kick-paper renders pages and figures and solves nothing (issue 32): its
/// `[dependencies]` name no model crate, no HDF5 and no thread pool, so the
/// compiler keeps it so. The declarations a page quotes (parameters,
/// statuses, number forms, Table 2 as printed) come through kick-study, which
/// re-exports them and no solver; its tests may solve, to check the pages.
#[test]
fn kick_paper_depends_on_no_solver_no_hdf5_and_no_thread_pool() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("crates/kick-paper/Cargo.toml");
    let text = std::fs::read_to_string(manifest).unwrap();
    let table: toml::Table = text.parse().unwrap();
    let dependencies: Vec<&str> = table["dependencies"].as_table().unwrap().keys().map(String::as_str).collect();
    let solving = [
        "kick-core",
        "kick-compliant",
        "kick-3d",
        "kick-flight",
        "kick-identify",
        "kick-bounce",
        "kick-restitution",
        "kick-impulse",
        "kick-leg",
        "kick-checks",
        "hdf5",
        "rayon",
    ];
    let named: Vec<&&str> = dependencies
        .iter()
        .filter(|d| solving.contains(d) || (d.starts_with("kick-") && !["kick-study", "kick-store"].contains(d)))
        .collect();
    assert!(named.is_empty(), "kick-paper depends on {named:?}");
    assert!(dependencies.contains(&"kick-study") && dependencies.contains(&"kick-store"), "{dependencies:?}");
}

/// kick-core holds the measurements as the model crates compare against
/// them and touches no file (issue 32: the model knows nothing of files):
/// the measurement file's name, opening and TOML parsing are kick-store's
/// (`kick_store::measurements`), and kick-core's `[dependencies]` name no
/// TOML parser.
#[test]
fn kick_core_reads_no_measurement_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let source = code(&std::fs::read_to_string(root.join("crates/kick-core/src/measurements.rs")).unwrap());
    let found: Vec<&str> = ["std::fs", "fs::", "File::open", "read_to_string", "MEASUREMENTS_FILE", "toml::", "Path"]
        .into_iter()
        .filter(|s| source.contains(s))
        .collect();
    assert!(found.is_empty(), "crates/kick-core/src/measurements.rs reads a file: {found:?}");
    let manifest: toml::Table = std::fs::read_to_string(root.join("crates/kick-core/Cargo.toml")).unwrap().parse().unwrap();
    let dependencies = manifest["dependencies"].as_table().unwrap();
    assert!(!dependencies.contains_key("toml"), "kick-core's [dependencies] name toml");
    let store = code(&std::fs::read_to_string(root.join("crates/kick-store/src/measurements.rs")).unwrap());
    assert!(store.contains("pub const MEASUREMENTS_FILE") && store.contains("pub fn read("), "kick_store::measurements lost its reader");
}
