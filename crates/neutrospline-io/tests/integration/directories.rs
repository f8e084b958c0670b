//! A directory where a file is expected: every reader says that the path is a directory and
//! what it reads in its place (issue 23: `import DIR.dxf` advised a .csv, .toml or .json file).

use neutrospline::Family;
use neutrospline_io::{load, load_data, load_points, read_whole, ReadError, ReadOptions};

#[test]
fn every_reader_names_the_directory_and_what_it_reads() {
    let dir = tempfile::tempdir().unwrap();
    let path = |name: &str| {
        let path = dir.path().join(name);
        std::fs::create_dir(&path).unwrap();
        path
    };
    let shown = |path: &std::path::Path| path.display().to_string();
    let message = |result: Result<(), ReadError>| {
        let error = result.unwrap_err();
        assert!(matches!(error, ReadError::IsDirectory { .. }), "{error:?}");
        error.to_string()
    };
    for name in ["m.csv", "m.toml", "m.json"] {
        let p = path(name);
        assert_eq!(
            message(load(&p, &ReadOptions::default()).map(drop)),
            format!(
                "{}: cannot read: it is a directory (give a .csv, .tsv, .toml or .json file, or a \
                 spreadsheet)",
                shown(&p)
            )
        );
    }
    let p = path("data.csv");
    assert_eq!(
        message(load_data(&p, Family::Neutrosophic).map(drop)),
        format!(
            "{}: cannot read: it is a directory (give a .csv file of data points)",
            shown(&p)
        )
    );
    let p = path("points.csv");
    assert_eq!(
        message(load_points(&p).map(drop)),
        format!(
            "{}: cannot read: it is a directory (give a .csv file of query points)",
            shown(&p)
        )
    );
    let p = path("drawing.dxf");
    assert_eq!(
        message(read_whole(&p, 1000, "a .dxf file").map(drop)),
        format!(
            "{}: cannot read: it is a directory (give a .dxf file)",
            shown(&p)
        )
    );
}
