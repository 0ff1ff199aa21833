#!/bin/sh
# The GPU check: the ecosystem's camera path at 1920x1080 with a 2048² perspective shadow map,
# headless through EGL (the device platform on an NVIDIA driver), with each sampler (cpu, gpu),
# and the medians of its frame, pass and host times after 3 warm-up frames, timed without writing
# images (--aov none: a GPU left idle while a PNG is encoded clocks down, and an H200's 1080p frames
# then took 78 ms instead of 17). Frame 0's colour and shadow images are kept, to hold against the
# same frame rendered on llvmpipe. With the GPU stages' times (--stats' stage_ms).
#
#   gpu_check.sh [OUT] [FRAMES]   (default OUT gpu_check, FRAMES 40)
#
# Runs from the folder scripts/gpu_bundle.sh makes (its launcher beside this file) or from the
# repository (build/ecoview).
set -eu
here="$(cd "$(dirname "$0")" && pwd)"
out="${1:-gpu_check}"
frames="${2:-40}"
warmup=3
if [ -x "$here/ecoview" ]; then ecoview="$here/ecoview"; else ecoview="$here/../build/ecoview"; fi
[ "$frames" -gt "$warmup" ] || { echo "gpu_check: FRAMES must be more than $warmup" >&2; exit 2; }

# glvnd finds the driver's EGL by a vendor file; some machines keep NVIDIA's beside the driver.
if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ] && ! ls /usr/share/glvnd/egl_vendor.d/*.json /etc/glvnd/egl_vendor.d/*.json >/dev/null 2>&1; then
  for vendor in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/lib/nvidia/egl_vendor.d/10_nvidia.json; do
    if [ -f "$vendor" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"; break; fi
  done
fi

mkdir -p "$out"
for sampler in cpu gpu; do
  "$ecoview" capture --scene ecosystem --path ecosystem --size 1920x1080 --shadow-size 2048 --method psm \
    --sampler "$sampler" --frames "0:$frames" --aov none --stats "$out/stats_$sampler.json" --out "$out/frames_$sampler" --force
  "$ecoview" capture --scene ecosystem --path ecosystem --size 1920x1080 --shadow-size 2048 --method psm \
    --sampler "$sampler" --frames 0:1 --aov color,shadow --out "$out/frame0_$sampler" --force >/dev/null

  # The stats file has one "key": value per line, a frame's GPU stages in "stage_ms" (ecoview
  # writes it so).
  awk -v warmup="$warmup" -v frames="$frames" -v sampler="$sampler" '
    function median(key,   n, i, j, t, v) {
      n = count[key]
      for (i = 1; i <= n; ++i) v[i] = values[key, i]
      for (i = 2; i <= n; ++i) { t = v[i]; for (j = i - 1; j >= 1 && v[j] > t; --j) v[j + 1] = v[j]; v[j + 1] = t }
      return n == 0 ? 0 : (n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2)
    }
    function key_value(line) { gsub(/^ *"|,$/, "", line); split(line, kv, "\": "); key = kv[1]; value = kv[2] }
    /"frame":/ { key_value($0); frame = value }
    /"stage_ms": \{/ { in_stages = 1; next }
    in_stages && /}/ { in_stages = 0; next }
    in_stages { key_value($0); pending["stage " key] = value; if (!(("stage " key) in seen)) { seen["stage " key] = 1; stages[++stage_count] = key } }
    /"(render_ms|host_ms|sample_ms|shadow_pass_ms|frame_pass_ms|points|shadow_points)":/ { key_value($0); pending[key] = value }
    /^  }/ {
      if (frame >= warmup) for (k in pending) values[k, ++count[k]] = pending[k]
      delete pending
    }
    END {
      render = median("render_ms")
      printf "gpu_check: ecosystem path, 1920x1080, psm 2048, --sampler %s, medians of frames %d to %d\n", sampler, warmup, frames - 1
      printf "  frame %.1f ms (%.1f fps), host %.1f ms, sampling %.1f ms, shadow pass %.1f ms, frame pass %.1f ms\n",
        render, (render > 0 ? 1000 / render : 0), median("host_ms"), median("sample_ms"), median("shadow_pass_ms"), median("frame_pass_ms")
      printf "  points %.0f, shadow points %.0f\n", median("points"), median("shadow_points")
      if (stage_count > 0) {
        printf "  GPU stages (ms):"
        for (i = 1; i <= stage_count; ++i) printf " %s %.2f%s", stages[i], median("stage " stages[i]), (i < stage_count ? "," : "\n")
      }
    }' "$out/stats_$sampler.json"
done
echo "gpu_check: frame 0 for the llvmpipe comparison in $out/frame0_cpu and $out/frame0_gpu"
