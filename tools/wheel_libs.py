"""The shared libraries a portable wheel carries, and the platform tag it can honestly claim (PEP 600).

The extension module links OpenEXR (and zlib through it), which most Linux systems lack. Like `auditwheel repair`,
which Debian 12 does not package, this copies every library the module needs beyond the manylinux set (glibc,
libstdc++, libgcc_s) into the package's `_libs/` folder and points the module's and the copies' run paths there
with patchelf. libEGL and libOSMesa are not among them: shadelab loads them at run time (gl/egl_library.h), as the
GL driver of the machine it runs on. tinygltf and stb are compiled into the module (src/third_party/).

The tag is `manylinux_2_<minor>_<arch>`, with <minor> the newest glibc symbol version the module or a copied
library needs, provided the libstdc++ symbol versions they need are within what that manylinux level promises.

    python3 tools/wheel_libs.py MODULE.so     # prints what would be copied, and the tag
"""

import os
import platform
import re
import shutil
import subprocess
import sys
from pathlib import Path

# Libraries every manylinux system provides (PEP 600's "system" libraries; auditwheel's policy lists): never
# copied. libEGL/libGL are loaded at run time and would be the machine's own anyway.
SYSTEM_LIBRARIES = re.compile(r"^(libc|libm|libdl|librt|libpthread|libutil|libresolv|libnsl|libgcc_s|libstdc\+\+|"
                              r"ld-linux[-.\w]*|linux-vdso|libEGL|libGL|libOpenGL|libGLdispatch)\.so")

# The newest libstdc++ symbol versions each glibc level's reference distributions carry (auditwheel's policy
# table: manylinux_2_34 is AlmaLinux 9 with GCC 11, manylinux_2_35 Ubuntu 22.04 with GCC 12).
GLIBCXX_LIMIT = {28: (3, 4, 25), 31: (3, 4, 28), 34: (3, 4, 29), 35: (3, 4, 30), 36: (3, 4, 30), 39: (3, 4, 33)}

FOLDER = "_libs"  # inside the package: shadelab/_libs/


def needed(path):
    """The DT_NEEDED names of an ELF file, in order."""
    out = subprocess.run(["readelf", "-d", str(path)], check=True, capture_output=True, text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


def resolved(path):
    """{soname: resolved path} for every library the loader would load for `path` (ldd)."""
    out = subprocess.run(["ldd", str(path)], check=True, capture_output=True, text=True).stdout
    found = {}
    for line in out.splitlines():
        match = re.match(r"\s*(\S+)\s+=>\s+(\S+)\s+\(", line)
        if match:
            found[match.group(1)] = match.group(2)
        elif "=> not found" in line:
            raise RuntimeError(f"{path}: {line.split()[0]} is not found on this machine")
    return found


def bundled(module):
    """The libraries to copy for `module`: {soname: path on this machine}, every non-system library it needs,
    directly or through another copied one."""
    paths = resolved(module)
    chosen = {}
    pending = [n for n in needed(module) if not SYSTEM_LIBRARIES.match(n)]
    while pending:
        name = pending.pop()
        if name in chosen:
            continue
        if name not in paths:
            raise RuntimeError(f"{module}: cannot tell where {name} is")
        chosen[name] = paths[name]
        pending += [n for n in needed(paths[name]) if not SYSTEM_LIBRARIES.match(n)]
    return chosen


def symbol_versions(path, prefix):
    """The versions of `prefix` (GLIBC, GLIBCXX) that `path` needs, as tuples."""
    out = subprocess.run(["objdump", "-T", str(path)], check=True, capture_output=True, text=True).stdout
    return {tuple(int(p) for p in v.split(".")) for v in re.findall(rf"\b{prefix}_([0-9][0-9.]*[0-9])\b", out)}


def platform_tag(files):
    """`manylinux_2_<minor>_<arch>` for the glibc and libstdc++ that `files` need; raises when libstdc++'s needs
    exceed what that manylinux level promises (the wheel would then be a plain linux_<arch> one, not portable)."""
    glibc = max((v for f in files for v in symbol_versions(f, "GLIBC")), default=(2, 17))
    glibcxx = max((v for f in files for v in symbol_versions(f, "GLIBCXX")), default=(3, 4))
    minor = glibc[1]
    limit = next((GLIBCXX_LIMIT[k] for k in sorted(GLIBCXX_LIMIT) if k >= minor), None)
    if limit is None or glibcxx > limit:
        raise RuntimeError(f"the module needs GLIBCXX_{'.'.join(map(str, glibcxx))}, newer than any manylinux level "
                           f"from glibc 2.{minor} promises")
    return f"manylinux_2_{minor}_{platform.machine()}"


def licence_file(path):
    """The Debian copyright file (licence and notices) of the package that installed the library at `path`."""
    real = os.path.realpath(path)
    for candidate in dict.fromkeys([str(path), real, re.sub(r"^/lib/", "/usr/lib/", real)]):
        found = subprocess.run(["dpkg-query", "-S", candidate], capture_output=True, text=True)
        if found.returncode == 0:
            package = found.stdout.split(":", 1)[0].split(",")[0].strip()
            copyright_file = Path("/usr/share/doc") / package / "copyright"
            if copyright_file.is_file():
                return copyright_file
    raise RuntimeError(f"{path}: no Debian copyright file found; a copied library must ship with its licence")


def bundle(module, package_dir):
    """Copies the libraries `module` needs beyond the system's into `package_dir`/_libs/, sets run paths so the
    module finds them there (and they find each other), puts each one's licence beside it (`_libs/licences/`), and
    returns the files the wheel's tag depends on."""
    if not shutil.which("patchelf"):
        raise RuntimeError("patchelf is missing (apt-get install patchelf; scripts/install-deps.sh installs it)")
    libs = Path(package_dir) / FOLDER
    libs.mkdir(parents=True, exist_ok=True)
    copies = []
    for name, source in sorted(bundled(module).items()):
        target = libs / name
        shutil.copyfile(source, target)
        os.chmod(target, 0o755)
        subprocess.run(["patchelf", "--set-rpath", "$ORIGIN", str(target)], check=True)
        (libs / "licences").mkdir(exist_ok=True)
        shutil.copyfile(licence_file(source), libs / "licences" / f"{name}.txt")
        copies.append(target)
    relative = os.path.relpath(libs, Path(module).parent)
    subprocess.run(["patchelf", "--set-rpath", f"$ORIGIN/{relative}", str(module)], check=True)
    return [Path(module), *copies]


def main(argv):
    if len(argv) != 2 or argv[1] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if len(argv) == 2 else 2
    module = Path(argv[1])
    if not module.is_file():
        print(f"wheel_libs: {module}: no such file", file=sys.stderr)
        return 1
    chosen = bundled(module)
    for name, path in sorted(chosen.items()):
        print(f"copy {name} ({path})")
    print(platform_tag([module, *chosen.values()]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
