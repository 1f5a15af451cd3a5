#!/usr/bin/env python3
"""Lists or patches the sections of an mpdem checkpoint, recomputing each patched section's CRC-32.

Used to rebuild the reproducers of docs/fuzzing.md (finding 4) from a seed after a checkpoint
format change, since the fuzzer's artifacts are byte strings of one format version.

  fuzz/patch_checkpoint.py IN                          list the sections (name, payload bytes)
  fuzz/patch_checkpoint.py IN OUT SECTION OFFSET HEX   write IN to OUT with the payload bytes of
                                                       SECTION at OFFSET replaced by HEX
  fuzz/patch_checkpoint.py IN OUT SECTION truncate N   ... with SECTION's payload cut to N bytes

Framing (src/io/checkpoint_format.hpp): magic (8 bytes), version (u32), then per section: name
length (u16), name, payload length (u64), payload, CRC-32 of name and payload (u32); native byte
order (little-endian here). A vector in a payload is its length (u64) followed by its elements.
"""
import struct
import sys
import zlib


def sections(b):
    at = 12
    while at < len(b):
        (n,) = struct.unpack_from("<H", b, at)
        name = bytes(b[at + 2 : at + 2 + n])
        at += 2 + n
        (size,) = struct.unpack_from("<Q", b, at)
        at += 8
        yield name.decode(), bytes(b[at : at + size])
        at += size + 4


def main(argv):
    data = open(argv[1], "rb").read()
    if len(argv) == 2:
        print(f"{data[:8].decode(errors='replace')} format {struct.unpack_from('<I', data, 8)[0]}")
        for name, payload in sections(data):
            print(f"{name:20s} {len(payload):6d} bytes")
        return 0
    out_file, target, where, what = argv[2], argv[3], argv[4], argv[5]
    out = bytearray(data[:12])
    found = False
    for name, payload in sections(data):
        if name == target:
            found = True
            if where == "truncate":
                payload = payload[: int(what)]
            else:
                at, patch = int(where), bytes.fromhex(what)
                if at + len(patch) > len(payload):
                    sys.exit(f"patch beyond the end of section '{name}' ({len(payload)} bytes)")
                payload = payload[:at] + patch + payload[at + len(patch) :]
        raw = name.encode()
        crc = zlib.crc32(payload, zlib.crc32(raw))
        out += struct.pack("<H", len(raw)) + raw + struct.pack("<Q", len(payload)) + payload + struct.pack("<I", crc)
    if not found:
        sys.exit(f"no section '{target}'")
    open(out_file, "wb").write(out)
    return 0


if __name__ == "__main__":
    if len(sys.argv) not in (2, 6):
        sys.exit(__doc__)
    sys.exit(main(sys.argv))
