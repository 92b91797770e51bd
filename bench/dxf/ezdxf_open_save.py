"""ezdxf's side of the benchmark: readfile, then saveas; prints the two times in seconds."""
import sys
import time

import ezdxf

t0 = time.perf_counter()
doc = ezdxf.readfile(sys.argv[1])
t1 = time.perf_counter()
doc.saveas(sys.argv[2])
t2 = time.perf_counter()
print(f"open_s {t1 - t0:.4f}")
print(f"save_s {t2 - t1:.4f}")
