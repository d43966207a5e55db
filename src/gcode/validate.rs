//! A post checked once, field by field, before any program is written
//! with it: lengths and characters of its texts, templates' variables,
//! number ranges, and a program end the controller accepts.

use super::check::{
    check_lines, check_num, check_text, check_word, err, has_program_end, PostError,
};
use super::post::{Format, Post};
use crate::text;

impl Post {
    /// Checks every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), PostError> {
        check_text("name", &self.name, 80)?;
        if !(1..=6).contains(&self.decimals) {
            let d = self.decimals;
            return Err(err(
                "decimals",
                text!("{d} is not between 1 and 6"; "{d} não está entre 1 e 6"),
            ));
        }
        check_num("chord", self.chord, 1e-4, 10.0)?;
        if self.incremental && (self.format != Format::Gcode || self.knife.is_some()) {
            return Err(err(
                "incremental",
                text!("G91 is written by G-code posts without a knife (this one's rows or knife turns are its own)";
                      "G91 é escrito por pós G-code sem faca (as linhas ou os giros de faca deste são próprios)"),
            ));
        }
        check_num("segment_length", self.segment_length, 0.0, 1000.0)?;
        if !(self.max_arc_sweep_deg > 0.0 && self.max_arc_sweep_deg <= 180.0) {
            let a = self.max_arc_sweep_deg;
            return Err(err(
                "max_arc_sweep_deg",
                text!("{a} is not above 0 and at most 180"; "{a} não é maior que 0 e no máximo 180"),
            ));
        }
        if let Some(n) = &self.line_numbers {
            if n.step == 0 || n.step > 1000 {
                return Err(err(
                    "line_numbers.step",
                    text!("not between 1 and 1000"; "fora de 1 a 1000"),
                ));
            }
            if n.start > 100_000_000 {
                return Err(err(
                    "line_numbers.start",
                    text!("above 100000000"; "acima de 100000000"),
                ));
            }
            if n.width > 9 {
                return Err(err("line_numbers.width", text!("above 9"; "acima de 9")));
            }
        }
        check_lines("unnumbered", &self.unnumbered, false)?;
        check_text("block_prefix", &self.block_prefix, 8)?;
        check_text("block_suffix", &self.block_suffix, 8)?;
        check_text("word_separator", &self.word_separator, 2)?;
        check_lines("program_start", &self.program_start, true)?;
        check_lines("header", &self.header, true)?;
        check_lines("footer", &self.footer, true)?;
        check_lines("program_end", &self.program_end, true)?;
        check_lines("probe", &self.probe, true)?;
        check_lines("torch_on", &self.torch_on, true)?;
        check_lines("dwell", &self.dwell, true)?;
        check_lines("after_pierce", &self.after_pierce, true)?;
        check_lines("thc_on", &self.thc_on, true)?;
        check_lines("thc_off", &self.thc_off, true)?;
        check_lines("torch_off", &self.torch_off, true)?;
        check_lines("spot", &self.spot, true)?;
        check_lines("mark_on", &self.mark_on, true)?;
        check_lines("mark_off", &self.mark_off, true)?;
        check_lines("thc_lock", &self.thc_lock, true)?;
        check_lines("thc_unlock", &self.thc_unlock, true)?;
        check_lines("small_hole_on", &self.small_hole_on, true)?;
        check_lines("small_hole_off", &self.small_hole_off, true)?;
        check_lines("comp_left", &self.comp_left, true)?;
        check_lines("comp_right", &self.comp_right, true)?;
        check_lines("comp_off", &self.comp_off, true)?;
        check_lines("tab_off", &self.tab_off, true)?;
        check_lines("tab_on", &self.tab_on, true)?;
        if self.tab_off.is_empty() != self.tab_on.is_empty() {
            return Err(err(
                "tab_on",
                text!("tab_off and tab_on go together (both empty: the torch goes off and pierces again)";
                      "tab_off e tab_on andam juntos (ambos vazios: a tocha desliga e perfura de novo)"),
            ));
        }
        check_lines("pass_z", &self.pass_z, true)?;
        check_lines("pass_retract", &self.pass_retract, true)?;
        check_lines("tool_change", &self.tool_change, true)?;
        check_num("switch_offset", self.switch_offset, 0.0, 100.0)?;
        check_num("safe_height", self.safe_height, 0.0, 1000.0)?;
        check_num("retract_height", self.retract_height, 0.0, 1000.0)?;
        check_num("probe_feed", self.probe_feed, 1.0, 1e5)?;
        check_num("probe_distance", self.probe_distance, 0.0, 1000.0)?;
        check_word("rapid", &self.rapid)?;
        check_word("line", &self.line)?;
        check_word("cw", &self.cw)?;
        check_word("ccw", &self.ccw)?;
        check_num("rapid_speed", self.rapid_speed, 1.0, 1e6)?;
        if let Some(k) = &self.knife {
            if !matches!(k.axis.as_str(), "A" | "B" | "C") {
                let axis = &k.axis;
                return Err(err(
                    "knife.axis",
                    text!("'{axis}' is not A, B or C"; "'{axis}' não é A, B ou C"),
                ));
            }
            check_num("knife.lift_angle_deg", k.lift_angle_deg, 0.0, 180.0)?;
            if self.format != Format::Gcode {
                return Err(err(
                    "knife",
                    text!("only G-code posts have a rotary axis";
                          "só pós-processadores de G-code têm eixo rotativo"),
                ));
            }
        }
        if self.format == Format::Gcode {
            if self.torch_off.is_empty() {
                return Err(err(
                    "torch_off",
                    text!("a G-code post must switch the torch off";
                          "um pós-processador de G-code deve desligar a tocha"),
                ));
            }
            if !has_program_end(&self.footer) {
                return Err(err(
                    "footer",
                    text!("must end the program with M2 or M30";
                          "deve terminar o programa com M2 ou M30"),
                ));
            }
        }
        Ok(())
    }
}
