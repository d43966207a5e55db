//! The writer's comments and text taken as it is (moved from writer.rs as they were).

use super::*;

#[test]
fn a_cut_comment_is_what_comment_writes() {
    let plan = CutPlan::default();
    let job = super::super::JobInfo::from_process(&crate::process::Process::DEFAULT);
    for style in [
        CommentStyle::Parens,
        CommentStyle::Semicolon,
        CommentStyle::Dollar,
        CommentStyle::None,
    ] {
        let post = Post {
            comments: style,
            ..Post::default()
        };
        for (cut, part, what, contour) in [
            (1, Some(1), "hole", Some(1)),
            (137_256, None, "small hole", Some(99)),
            (u64::MAX, Some(u64::MAX), "outer", None),
            (7, None, "mark", None),
            (12, Some(0), "open", Some(10)),
        ] {
            let dash = |n: Option<u64>| n.map_or("-".to_string(), |n| n.to_string());
            let mut a = Writer::new(&post, &plan, &job);
            a.comment(&format!(
                "cut {cut} part {} {what} contour {}",
                dash(part),
                dash(contour)
            ));
            let mut b = Writer::new(&post, &plan, &job);
            b.cut_comment(cut, part, what, contour);
            assert_eq!(b.finish(), a.finish(), "{style:?} {cut} {what}");
        }
    }
}

#[test]
fn text_taken_as_it_is_is_what_sanitising_writes() {
    // Random strings over delimiters, blanks, controls, non-ASCII and
    // plain text, of every length around the 120 limit.
    let alphabet: Vec<char> = "ab Z09-.,:_()#;%$\t\n\u{7f}é€ ".chars().collect();
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let (mut plain, mut n) = (0, 0);
    for _ in 0..20000 {
        x = crate::test_rng::Xorshift(x).next();
        let len = (x % 130) as usize;
        // Mostly letters, so that many strings are plain.
        let t: String = (0..len)
            .map(|i| {
                let k = (x.rotate_left(i as u32 * 7) % 97) as usize;
                if k < alphabet.len() {
                    alphabet[k]
                } else {
                    'q'
                }
            })
            .collect();
        n += 1;
        if is_sanitised(&t) {
            plain += 1;
            assert_eq!(super::super::sanitise(&t), t);
        } else {
            assert_ne!(super::super::sanitise(&t), t, "{t:?}");
        }
    }
    assert!(plain > n / 20 && plain < n, "{plain} of {n}");
}
