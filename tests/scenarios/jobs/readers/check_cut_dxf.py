#!/usr/bin/python3
# tests/scenarios/jobs/readers/check_cut_dxf.py: reads a cut.dxf with ezdxf (an independent DXF
# reader) and prints key=value facts the scenario test checks; exit 1 if ezdxf refuses the file.
import sys

import ezdxf
from ezdxf import bbox

path = sys.argv[1]
doc = ezdxf.readfile(path)
audit = doc.audit()
print("version=" + doc.dxfversion)
print("audit_errors=%d" % len(audit.errors))
print("insunits=%s" % ("yes" if "$INSUNITS" in doc.header else "no"))
print("ltype_continuous=%s" % ("yes" if "CONTINUOUS" in doc.linetypes else "no"))
for layer in ("1", "4", "7", "8", "13", "14", "15"):
    print("layer_%s=%s" % (layer, "yes" if layer in doc.layers else "no"))

# Entities written (top-level, in blocks and model space) against those ezdxf loaded.
written = 0
section = None
skip = {"SECTION", "ENDSEC", "BLOCK", "ENDBLK", "VERTEX", "SEQEND", "TABLE", "ENDTAB", "EOF"}
lines = open(path, encoding="ascii", errors="replace").read().split("\n")
for i in range(0, len(lines) - 1, 2):
    code, value = lines[i].strip(), lines[i + 1].strip()
    if code == "2" and lines[i - 2].strip() == "0" and lines[i - 1].strip() == "SECTION":
        section = value
    if code == "0" and section in ("BLOCKS", "ENTITIES") and value not in skip:
        written += 1
loaded = len(doc.modelspace())
drill_kinds = set()
for block in doc.blocks:
    if block.name.startswith("*"):
        continue
    loaded += len(block)
    for e in block:
        if e.dxf.layer == "13":
            drill_kinds.add(e.dxftype())
print("entities_written=%d" % written)
print("entities_loaded=%d" % loaded)
print("drill_kinds=" + ",".join(sorted(drill_kinds)))
texts = [e.dxf.text for e in doc.modelspace().query("TEXT")]
print("style_units=%s" % ("yes" if "Units: METRIC" in texts else "no"))
print("style_name=%s" % ("yes" if any(t.startswith("Style Name: ") for t in texts) else "no"))
ext = bbox.extents(doc.modelspace())
print("extents=%.3f,%.3f,%.3f,%.3f" % (ext.extmin.x, ext.extmin.y, ext.extmax.x, ext.extmax.y))
print("header_extmin=%.3f,%.3f" % tuple(doc.header["$EXTMIN"])[:2])
print("header_extmax=%.3f,%.3f" % tuple(doc.header["$EXTMAX"])[:2])
