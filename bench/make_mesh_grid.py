# Writes a grid of n × n quads (2n² triangles) in z = 0, with uvs and one normal, as OBJ and as
# binary PLY: the large meshes of BENCHMARKS.md ("Mesh loading"). Usage: make_mesh_grid.py N OUT
# (writes OUT.obj and OUT.ply).
import struct, sys
n = int(sys.argv[1]); out = sys.argv[2]
with open(out + ".obj", "w") as f:
    for j in range(n + 1):
        for i in range(n + 1):
            f.write(f"v {i / n:.6f} {j / n:.6f} {0.01 * ((i * 7 + j * 13) % 17) / 17:.6f}\n")
    for j in range(n + 1):
        for i in range(n + 1):
            f.write(f"vt {i / n:.6f} {j / n:.6f}\n")
    f.write("vn 0 0 1\n")
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i + 1; b = a + 1; c = b + n + 1; d = a + n + 1
            f.write(f"f {a}/{a}/1 {b}/{b}/1 {c}/{c}/1\nf {a}/{a}/1 {c}/{c}/1 {d}/{d}/1\n")
with open(out + ".ply", "wb") as f:
    nv = (n + 1) ** 2; nf = 2 * n * n
    f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\nproperty float z\nelement face {nf}\nproperty list uchar int vertex_indices\nend_header\n".encode())
    f.write(b"".join(struct.pack("<3f", i / n, j / n, 0.01 * ((i * 7 + j * 13) % 17) / 17) for j in range(n + 1) for i in range(n + 1)))
    faces = []
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i; b = a + 1; c = b + n + 1; d = a + n + 1
            faces.append(struct.pack("<B3i", 3, a, b, c)); faces.append(struct.pack("<B3i", 3, a, c, d))
    f.write(b"".join(faces))
