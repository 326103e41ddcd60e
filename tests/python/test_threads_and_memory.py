"""A render releases the GIL, and a thousand renders leak nothing."""
import os
import signal
import threading
import time
import unittest

import raylab
from support import small


def rss_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


class ThreadsAndMemory(unittest.TestCase):
    def test_a_render_lets_another_python_thread_run(self):
        scene = small("default.json", 96, 54)
        raylab.render(scene, spp=1)   # compiled and warm
        ticks = []
        done = threading.Event()

        def count():
            while not done.is_set():
                ticks.append(time.perf_counter())
                time.sleep(0.001)

        thread = threading.Thread(target=count)
        image = None
        start = time.perf_counter()
        thread.start()
        try:
            image = raylab.render(scene, spp=48)
        finally:
            end = time.perf_counter()
            done.set()
            thread.join()
        self.assertEqual(image.meta["spp"], 48)
        during = [t for t in ticks if start < t < end]
        # Holding the GIL would stop the counter for the whole render (> 0.1 s here); released,
        # it ticks every millisecond or so. 20 ticks is far below that, far above a held GIL's 0–1.
        self.assertGreater(end - start, 0.1)
        self.assertGreaterEqual(len(during), 20, f"{len(during)} ticks in a {end - start:.2f} s render")

    def test_renders_from_two_threads_give_each_its_own_image(self):
        scenes = [small("default.json", 16, 16), small("cornell_box.json", 16, 16)]
        alone = [raylab.render(s, spp=2, seed=3) for s in scenes]
        results = [None, None]

        def work(i):
            results[i] = raylab.render(scenes[i], spp=2, seed=3)

        threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for i in range(2):
            self.assertTrue((results[i] == alone[i]).all())

    def test_ctrl_c_stops_a_render_and_raises_keyboard_interrupt(self):
        scene = small("default.json", 96, 54)
        raylab.render(scene, spp=1)
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.perf_counter()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            raylab.render(scene, spp=1000000)   # hours, uninterrupted
        timer.join()
        self.assertLess(time.perf_counter() - start, 10.0)
        self.assertEqual(raylab.render(scene, spp=1).meta["spp"], 1)   # the GL thread is free again

    def test_a_thousand_renders_do_not_grow_memory(self):
        scene = small("default.json", 8, 8)
        for _ in range(50):   # warm: shader, caches, allocator pools
            raylab.render(scene, spp=1)
        before = rss_kib()
        for i in range(1000):
            image = raylab.render(scene, spp=1, seed=i)
            self.assertEqual(image.meta["spp"], 1)
        grown = rss_kib() - before
        # An 8x8 image is 1 KiB; a leak of anything per render (its image, its metadata, a GL
        # texture) would add 1000 of them. 4 MiB allows the allocator's own drift.
        self.assertLess(grown, 4096, f"RSS grew by {grown} KiB over 1000 renders")


if __name__ == "__main__":
    unittest.main()
