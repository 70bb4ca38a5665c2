#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets into tests/fuzz/corpus/<target>/ (committed; run
again only to change the seeds). Small valid files of each format plus a few near misses; the
JPEG seed is encoded by OpenCV (a one-off program built with c++), the results
seed is written by a built `fieldsight`."""
import bz2, json, os, struct, subprocess, sys, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
OUT = os.path.join(HERE, "corpus")


def put(target, name, data):
    os.makedirs(os.path.join(OUT, target), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(OUT, target, name), "wb") as f:
        f.write(data)


def strm_record(version, w, h, t, flipped=False):
    head = b"IMAG" + struct.pack("<iiid", version, w, h, t)
    if version >= 1:
        head += bytes([1 if flipped else 0])
    pixels = bytes((16 + i * 7) % 256 for i in range(w * h * 4))
    return head + pixels


def png(w, h, rgb):
    raw = b"".join(b"\0" + bytes(rgb) * w for _ in range(h))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def bmp(w, h, bgr):
    row = (bytes(bgr) * w).ljust((w * 3 + 3) // 4 * 4, b"\0")
    pixels = row * h
    head = b"BM" + struct.pack("<IHHI", 54 + len(pixels), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, w, h, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    return head + info + pixels


def main():
    # .strm: two version-1 records, a version-0 record, a flipped one; a sensor stream.
    put("strm", "two_v1", strm_record(1, 8, 6, 0.0) + strm_record(1, 8, 6, 33.3))
    put("strm", "v0", strm_record(0, 4, 4, 5.0))
    put("strm", "flipped", strm_record(1, 6, 4, 1.0, True) + strm_record(1, 6, 4, 2.0))
    put("strm", "truncated", strm_record(1, 8, 6, 0.0)[:60])
    names = "[0 HeadPitch , 1 Horizon , 2 Orientation ]\n[0 HeadPitch , 1 Horizon ]\n[[0], [1], [2]]\n[0, 1, 2]\n"
    put("sensor_strm", "two", names + "3 HeadPitch 10 1 0 0 0 0.25 Horizon 10 0 1 0 0 0.5 1 20 "
        "Orientation 10 0 1 0 0 0 0 0\n" + names + "2 HeadPitch 10 1 0 0 0 0.25 Horizon 10 0 0 0 0 0 0 0\n")
    put("sensor_strm", "names_only", names)

    # Colour tables. The fixed-size formats' harness repeats an input whose first byte is odd to
    # the format's size, so these seeds are a marker byte and one period of cells.
    put("lut", "classes", bytes([1]) + bytes(range(11)) * 3)
    put("lut", "bad_class", bytes([1, 0, 2, 200]))
    put("lut", "short", bytes([0]) + bytes(64))
    put("lut_nnmc", "classes", bytes([1]) + bytes(range(11)) * 3)
    put("lut_raw", "flags", bytes([1, 0, 1, 2, 4, 8, 16, 3, 24, 0]))
    c64 = struct.pack("<I", 64 ** 3 // 2) + bytes([3]) + struct.pack("<I", 64 ** 3 // 2) + bytes([0x85]) + struct.pack("<I", 0)
    put("lut_c64", "two_runs", c64)
    put("lut_c64", "overrun", struct.pack("<I", 64 ** 3 + 1) + bytes([1]) + struct.pack("<I", 0))
    put("lut_nnmc_bz2", "fields", bz2.compress(bytes([5]) * (1 << 20) + bytes([0]) * (1 << 20)))
    put("lut_nnmc_bz2", "short", bz2.compress(bytes([5]) * 1000))

    # JSON documents.
    with open(os.path.join(ROOT, "sample_streams/lab1/annotations.json")) as f:
        ann = json.load(f)
    frames = dict(list(ann["frames"].items())[:2])
    put("annotations", "two_frames", json.dumps({"format": ann["format"], "frames": frames}))
    put("annotations", "ball", json.dumps({"format": ann["format"], "frames": {"a.png": {
        "done": False, "balls": [{"x": 10.5, "y": 4, "radius": 3}]}}}))
    exe = os.path.join(ROOT, "build/app/fieldsight")
    if os.path.exists(exe):
        out = subprocess.run([exe, "run", os.path.join(ROOT, "sample_streams/lab1"), "--limit", "2",
                              "--out", "-"], capture_output=True, check=True).stdout
        put("results", "two_frames", out)
    put("params", "ball", '{"format": "fieldsight-params/1", "stages": {"ball": {"min_radius": 2.5}, '
        '"transitions": {"goal_colour": 9}}}')
    put("lut_samples", "two", json.dumps({"format": "fieldsight-lut-samples/1", "smoothing": 1,
        "samples": [{"frame": "frame_000000.png", "colour": "green", "polygon": [[0, 100], [50, 100], [50, 120]]},
                    {"frame": "frame_000001.png", "exclude": True, "polygon": [[1, 1], [5, 1], [5, 5], [1, 5]]}]}))
    put("bookmarks", "two", json.dumps({"format": "fieldsight-bookmarks/1", "bookmarks": [
        {"frame": 3, "name": "frame_000003.png", "note": "ball missed"}, {"frame": 10}]}))

    # An image folder: the manifest, and each image format of the one listed frame.
    put("stream_manifest", "two", json.dumps({"format": "fieldsight-stream/1", "camera": {"fov_deg": [60, 45]},
        "frames": [{"file": "frame_0.png", "horizon": [4, 6], "timestamp_ms": 0},
                   {"file": "frame_1.png", "timestamp_ms": 33.3}], "lut": "none.lut"}))
    put("stream_manifest", "bare", '{"format": "fieldsight-stream/1", "frames": ["frame_1.png"]}')
    put("stream_manifest", "orientation", json.dumps({"format": "fieldsight-stream/1", "orientation": 180,
        "frames": [{"file": "frame_0.png", "horizon": [4, 6]}]}))
    put("image_png", "green", png(12, 8, (60, 160, 40)))
    put("image_bmp", "green", bmp(12, 8, (40, 160, 60)))
    jpg = os.path.join(OUT, "image_jpg", "green")
    os.makedirs(os.path.dirname(jpg), exist_ok=True)
    program = ("#include <opencv2/imgcodecs.hpp>\nint main(int, char** argv) { "
               "cv::imwrite(std::string(argv[1]) + \".jpg\", cv::Mat(8, 12, CV_8UC3, "
               "cv::Scalar(40, 160, 60))); }\n")
    flags = ["-I/usr/include/opencv4", "-lopencv_imgcodecs", "-lopencv_core"]
    subprocess.run(["c++", "-x", "c++", "-", "-o", "/tmp/fieldsight_jpeg_seed"] + flags,
                   input=program, text=True, check=True)
    subprocess.run(["/tmp/fieldsight_jpeg_seed", jpg], check=True)
    os.replace(jpg + ".jpg", jpg)


if __name__ == "__main__":
    sys.exit(main())
