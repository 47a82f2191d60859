"""A real two-node Ray cluster on localhost: a head node and a second node, each a `ray start
--block` process group of its own (so the test stops exactly the processes it started), each
with one CPU and its own custom resource; render_frames must use both."""
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

import pytest

ray = pytest.importorskip("ray", reason="Ray is not installed (scripts/install-python installs it)")

from candela import distributed  # noqa: E402
from conftest import animated_scene  # noqa: E402

RAY_CLI = [sys.executable, "-m", "ray.scripts.scripts", "start", "--block", "--num-cpus=1",
           "--node-ip-address=127.0.0.1", "--disable-usage-stats"]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def stop(proc):
    """SIGTERM, then SIGKILL, to the node's whole process group (raylet, GCS, workers)."""
    for sig, wait in ((signal.SIGTERM, 20), (signal.SIGKILL, 10)):
        try:
            os.killpg(proc.pid, sig)
        except ProcessLookupError:
            return
        try:
            proc.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            pass


def connects(address, env):
    """Whether a fresh driver can join the cluster (a probe in its own process)."""
    probe = f"import ray; ray.init(address={address!r}); ray.shutdown()"
    try:
        return subprocess.run([sys.executable, "-c", probe], env=env, capture_output=True,
                              timeout=30).returncode == 0
    except subprocess.TimeoutExpired:
        return False


def wait_for(condition, seconds, what):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if condition():
            return
        time.sleep(0.5)
    pytest.fail(f"timed out after {seconds} s waiting for {what}")


def test_two_node_cluster_on_localhost(tmp_path, monkeypatch):
    assert not ray.is_initialized()
    port = free_port()
    address = f"127.0.0.1:{port}"
    # Token authentication (on by default in recent Ray) guards real clusters; this one is private
    # to the test. The driver (this process) must agree with the nodes.
    monkeypatch.setenv("RAY_AUTH_MODE", "disabled")
    env = dict(os.environ, RAY_USAGE_STATS_ENABLED="0", RAY_AUTH_MODE="disabled")
    log = open(tmp_path / "ray.log", "w")
    # Ray's own folder, short: its socket paths must stay under 108 bytes.
    temp_dir = tempfile.mkdtemp(prefix="candela-ray-")
    nodes = []
    try:
        nodes.append(subprocess.Popen(
            RAY_CLI + ["--head", f"--port={port}", "--include-dashboard=false",
                       f"--temp-dir={temp_dir}",
                       '--resources={"head_node": 1}'],
            env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True))
        wait_for(lambda: connects(address, env), 120, "the head node")
        nodes.append(subprocess.Popen(
            RAY_CLI + [f"--address={address}", '--resources={"second_node": 1}'],
            env=env, stdout=log, stderr=subprocess.STDOUT, start_new_session=True))
        ray.init(address=address, log_to_driver=False)
        wait_for(lambda: ray.cluster_resources().get("second_node", 0) >= 1, 90, "the second node")
        assert ray.cluster_resources().get("head_node") == 1
        assert len([n for n in ray.nodes() if n["Alive"]]) == 2

        path = tmp_path / "anim.json"
        path.write_text(json.dumps(animated_scene(frames=4, size=48, spp=3000)))
        # About a second per frame: while one node renders, the queued frames go to the other.
        results = distributed.render_frames(str(path), tmp_path / "frames", address=address)
        assert len({r["node"] for r in results}) == 2, results  # frames on both nodes
        assert sorted(os.listdir(tmp_path / "frames")) == [f"frame_{i:04d}.png" for i in range(4)]
    finally:
        ray.shutdown()
        for proc in reversed(nodes):
            stop(proc)
        log.close()
        shutil.rmtree(temp_dir, ignore_errors=True)
