#!/bin/sh
# Packs the built ecoview and the shared libraries it needs that are not part of a GL driver into
# one folder that runs on another x86-64 Linux machine with a GPU driver, through EGL's device
# platform: bin/ecoview, lib/ (glvnd's vendor-neutral libEGL and libGLdispatch travel too; the
# driver's own EGL library stays on that machine), the launcher `ecoview` and gpu_check.sh.
# glibc stays behind: that machine's must be at least this one's (2.36, Debian 12).
#
#   scripts/gpu_bundle.sh [FOLDER]     (default build/gpu_bundle; build first with scripts/setup.sh)
set -eu
cd "$(dirname "$0")/.."
out="${1:-build/gpu_bundle}"
binary="${ECOVIEW_BINARY:-build/ecoview}"  # the tests name theirs
limit_mib=60

[ -x "$binary" ] || { echo "gpu_bundle: $binary is missing; build it first with scripts/setup.sh" >&2; exit 2; }
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib"
cp "$binary" "$out/bin/ecoview"
strip "$out/bin/ecoview" 2>/dev/null || true

# Every library the loader resolves for the binary, but the C library's own parts, which must
# match that machine's kernel and loader.
ldd "$binary" | awk '$3 ~ /^\// {print $3}' | while read -r library; do
  case "$(basename "$library")" in
    libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|ld-linux*) continue ;;
  esac
  cp -L "$library" "$out/lib/"
done

cat > "$out/ecoview" <<'LAUNCHER'
#!/bin/sh
# ecoview with the libraries packed beside it.
here="$(cd "$(dirname "$0")" && pwd)"
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/bin/ecoview" "$@"
LAUNCHER
chmod +x "$out/ecoview"
cp scripts/gpu_check.sh "$out/gpu_check.sh"

size_mib=$(du -sm "$out" | cut -f1)
if [ "$size_mib" -ge "$limit_mib" ]; then
  echo "gpu_bundle: $out holds $size_mib MiB, more than $limit_mib MiB" >&2
  exit 1
fi
echo "gpu_bundle: $out ($size_mib MiB): $(ls "$out/lib" | wc -l) libraries; run $out/gpu_check.sh there"
