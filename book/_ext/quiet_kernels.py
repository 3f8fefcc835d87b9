"""Kernels started by the build talk to it over an encrypted transport (and so print no warning).

MyST-NB executes notebooks through jupyter-cache and nbclient, which start kernels with
jupyter_client's ``KernelManager``. Since ipykernel 7, a kernel given no CurveZMQ keys logs
``Kernel is running over TCP without encryption`` on every start. jupyter_client provisions keys
when ``KernelManager.transport_encryption`` is ``"auto"`` and the kernelspec declares support (as
ipykernel's does); nbclient offers no way to pass that setting, so it becomes the default here, in
the build process only, and only where pyzmq has CurveZMQ.
"""

from __future__ import annotations


def _encrypt_by_default() -> None:
    import zmq
    from jupyter_client.manager import KernelManager

    trait = KernelManager.class_traits().get("transport_encryption")
    if trait is not None and zmq.has("curve"):
        trait.default_value = "auto"


def setup(app):
    _encrypt_by_default()
    return {"parallel_read_safe": True, "parallel_write_safe": True}
