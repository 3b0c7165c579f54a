"""Peak RSS of GridMap.from_array on a 4096 x 4096 bool array (Linux ru_maxrss)."""
import resource, numpy as np, hyplan, time
n = 4096
occ = np.zeros((n, n), bool); occ[::7, :] = True; occ[:, ::5] = False  # touch every page
def rss(): return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # MiB (Linux: KiB)
base = rss()
t0 = time.perf_counter(); m = hyplan.GridMap.from_array(occ); dt = time.perf_counter() - t0
after = rss()
z = m.zones
print(f"array {occ.nbytes/2**20:.1f} MiB; peak RSS {base:.1f} -> {after:.1f} MiB (+{after-base:.1f} MiB) in {dt*1e3:.1f} ms; zones view shares memory with the map: {z.base is not None}, peak after .zones {rss():.1f} MiB")
