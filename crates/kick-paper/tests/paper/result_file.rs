//! `ResultWriter` / `ResultFile`: a group layout of one's own, read back
//! independently with the hdf5 crate, units and provenance on everything.

use kick_store::h5::read_str_attr;
use kick_store::{Column, Provenance, ResultFile, ResultWriter};

#[test]
fn result_files_round_trip_with_units_and_provenance() {
    let dir = crate::scratch("result-file");
    let path = dir.join("r.h5");
    let provenance = Provenance::now("r", "test (command line)", "text of the run");
    let w = ResultWriter::create(&path, &provenance, &kick_store::layouts::HISTORY).unwrap();
    w.column("a/b", &Column::new("time", "s"), &[0.0, 1e-3, 2e-3]).unwrap();
    w.scalar("a", "chi_square", "1", 320.78).unwrap();
    w.strings("a", "names", &["x".to_string(), "y z".to_string()]).unwrap();
    w.text("a/b", "parameter", "stiffness").unwrap();
    assert!(!path.exists(), "written under a temporary name until finished");
    assert_eq!(w.finish().unwrap(), path);
    let left: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(left, ["r.h5"], "no temporary or lock file left");

    // Independently, with the hdf5 crate.
    let file = hdf5::File::open(&path).unwrap();
    assert_eq!(read_str_attr(&file, "layout").as_deref(), Some("history"));
    assert_eq!(kick_store::h5::read_u64_attr(&file, "layout_version"), Some(kick_store::layouts::HISTORY.version));
    assert_eq!(read_str_attr(&file, "experiment_text").as_deref(), Some("text of the run"));
    assert_eq!(read_str_attr(&file, "tool").as_deref(), Some("kick"));
    let time = file.dataset("a/b/time").unwrap();
    assert_eq!(time.read_raw::<f64>().unwrap(), vec![0.0, 1e-3, 2e-3]);
    assert_eq!(read_str_attr(&time, "units").as_deref(), Some("s"));
    drop(file);

    let r = ResultFile::open(&path).unwrap();
    let (column, values) = r.column("a/b/time").unwrap();
    assert_eq!((column.name.as_str(), column.unit.as_str(), values), ("time", "s", vec![0.0, 1e-3, 2e-3]));
    assert_eq!(r.scalar("a/chi_square").unwrap(), 320.78);
    assert_eq!(r.strings("a/names").unwrap(), ["x", "y z"]);
    assert_eq!(r.text("a/b", "parameter").unwrap(), "stiffness");
    assert_eq!(r.text("", "layout").unwrap(), "history");
    assert_eq!(r.members("a").unwrap(), ["b", "chi_square", "names"]);
    assert!(r.exists("a/b/time") && r.exists("a/b") && !r.exists("a/c") && !r.exists("a/b/time/x"));
    // Errors name the path.
    assert!(r.scalar("a/b/time").unwrap_err().to_string().contains("a/b/time: 3 values"));
    assert!(r.values("a/missing").unwrap_err().to_string().contains("a/missing"));
    assert!(r.text("a", "nothing").unwrap_err().to_string().contains("nothing"));
    std::fs::remove_dir_all(&dir).ok();
}
