//! Tests of `qtplasmac`.

use super::*;

/// A file as QtPlasmaC itself writes it (its key alignment, a blank line
/// after each material), with a comment header and a hand-edited line.
const FILE: &str = "# plasmac material file\n# example only, may be deleted\n\
[MATERIAL_NUMBER_1]\nNAME               = Mild 3mm\nKERF_WIDTH         = 1.5\nPIERCE_HEIGHT      = 3.8\n\
PIERCE_DELAY       = 0.4\nPUDDLE_JUMP_HEIGHT = 0\nPUDDLE_JUMP_DELAY  = 0\nCUT_HEIGHT         = 1.5\n\
CUT_SPEED          = 3300\nCUT_AMPS           = 45\nCUT_VOLTS          = 122\nPAUSE_AT_END       = 0\n\
GAS_PRESSURE       = 0\nCUT_MODE           = 1\n\n[MATERIAL_NUMBER_7]\nNAME = Stainless 2\r\nKERF_WIDTH=1.2\n\
THC                = 1\nPIERCE_HEIGHT      = 3\nPIERCE_DELAY       = 0.3\nCUT_HEIGHT         = 1\n\
CUT_SPEED          = 2500.0\n";

#[test]
fn a_material_file_round_trips_byte_for_byte() {
    let f = MaterialFile::parse(FILE).unwrap();
    assert_eq!(f.write(), FILE);
    let lib = f.library().unwrap();
    assert_eq!(lib.entries.len(), 2);
    let (a, b) = (&lib.entries[0], &lib.entries[1]);
    assert_eq!(
        (a.name.as_str(), a.kerf, a.feed, a.pierce_delay),
        ("Mild 3mm", 1.5, 3300.0, 0.4)
    );
    assert_eq!(
        (a.amps, a.volts, a.cut_mode),
        (Some(45.0), Some(122.0), Some(1.0))
    );
    assert_eq!(
        (b.name.as_str(), b.kerf, b.feed, b.thc),
        ("Stainless 2", 1.2, 2500.0, Some(1.0))
    );
}

#[test]
fn a_library_written_as_a_material_file_reads_back_the_same() {
    let lib = Library::starter();
    let text = MaterialFile::from_library(&lib).write();
    assert!(text.contains("[MATERIAL_NUMBER_1]\nNAME               = Mild steel 1.5 mm 45 A (example)\nKERF_WIDTH         = 1.5\n"), "{text}");
    let back = MaterialFile::parse(&text).unwrap();
    assert_eq!(back.write(), text);
    let again = back.library().unwrap();
    let plasma: Vec<&Entry> = lib
        .entries
        .iter()
        .filter(|e| e.process == Process::Plasma)
        .collect();
    assert_eq!(again.entries.len(), plasma.len());
    for (x, y) in again.entries.iter().zip(plasma) {
        assert_eq!(
            (&x.name, x.kerf, x.feed, x.pierce_delay, x.cut_height),
            (&y.name, y.kerf, y.feed, y.pierce_delay, y.cut_height)
        );
    }
}

#[test]
fn broken_files_name_the_material_and_field() {
    let e = MaterialFile::parse(
        "[MATERIAL_NUMBER_1]\nNAME = A\nPIERCE_HEIGHT = 3\nPIERCE_DELAY = 0\nCUT_HEIGHT = 1\n",
    )
    .unwrap()
    .library()
    .unwrap_err();
    assert_eq!(
        (e.entry.as_deref(), e.field),
        (Some("A"), Some("CUT_SPEED"))
    );
    let e = MaterialFile::parse(
        "[MATERIAL_NUMBER_2]\nPIERCE_HEIGHT = 3\nPIERCE_DELAY = x\nCUT_HEIGHT = 1\nCUT_SPEED = 9\n",
    )
    .unwrap()
    .library()
    .unwrap_err();
    assert_eq!(
        (e.entry.as_deref(), e.field),
        (Some("Material 2"), Some("PIERCE_DELAY"))
    );
    assert!(MaterialFile::parse("[MATERIAL_NUMBER_1000000]\n").is_err());
    assert!(MaterialFile::parse("[MATERIAL_NUMBER_1]\n[MATERIAL_NUMBER_1]\n").is_err());
    assert!(MaterialFile::parse("hello\n").is_err());
    assert!(MaterialFile::parse("[MATERIAL_NUMBER_1]\nG0 X0\n").is_err());
    // A name with a line break cannot add a line to the file.
    let mut lib = Library::starter();
    lib.entries[0].name = "A\nCUT_SPEED = 1".into();
    let text = MaterialFile::from_library(&lib).write();
    assert!(!text.contains("\nCUT_SPEED = 1"), "{text}");
}

#[test]
fn an_imported_file_exports_as_read_and_edits_touch_their_own_section() {
    let lib = Library::from_text(FILE).unwrap();
    assert_eq!(lib.entries[1].number, Some(7));
    assert_eq!(lib.to_material_file(), FILE);
    // Through the page's storage (JSON) and back.
    let lib = Library::from_json(&lib.to_json()).unwrap();
    assert_eq!(lib.to_material_file(), FILE);
    // One entry edited, one added: the other section and the header stay as read.
    let mut edited = lib.clone();
    edited.entries[0].feed = 3000.0;
    let mut added = Library::starter().entries[0].clone();
    added.name = "New".into();
    edited.entries.push(added);
    let text = edited.to_material_file();
    assert!(text.starts_with("# plasmac material file\n# example only, may be deleted\n[MATERIAL_NUMBER_1]\nNAME               = Mild 3mm\n"), "{text}");
    assert!(text.contains("CUT_SPEED          = 3000\n"), "{text}");
    assert!(
        text.contains("[MATERIAL_NUMBER_7]\nNAME = Stainless 2\r\nKERF_WIDTH=1.2\n"),
        "{text}"
    );
    assert!(
        text.contains(
            "CUT_SPEED          = 2500.0\n[MATERIAL_NUMBER_2]\nNAME               = New\n"
        ),
        "{text}"
    );
    let back = Library::from_text(&text).unwrap();
    let numbers: Vec<Option<u32>> = back.entries.iter().map(|e| e.number).collect();
    assert_eq!(numbers, [Some(1), Some(7), Some(2)]);
    assert_eq!(back.entries[0].feed, 3000.0);
}
