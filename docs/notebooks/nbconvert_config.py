# nbconvert configuration for executing the notebooks here headlessly on Debian 12:
#   jupyter nbconvert --to notebook --execute --config docs/notebooks/nbconvert_config.py docs/notebooks/phong-lab.ipynb
# Debian 12 ships ipywidgets 6, which opens widget comms with protocol 1 (the state is the message's data), while
# its nbclient 0.7 reads protocol 2 (data["state"]) and stops with KeyError: 'state' on the first widget. A
# headless run has no frontend to draw widgets anyway, so comms of the old protocol are left unmirrored; the
# kernel side (sliders, callbacks) runs as in a browser. Interactive Jupyter needs none of this.
import nbclient.client

_mirror_widget = nbclient.client.NotebookClient.on_comm_open_jupyter_widget


def _on_comm_open_jupyter_widget(self, msg):
    if "state" not in msg["content"]["data"]:
        return None
    return _mirror_widget(self, msg)


nbclient.client.NotebookClient.on_comm_open_jupyter_widget = _on_comm_open_jupyter_widget

# The widgets' state is still saved with the executed notebook (metadata.widgets, as nbclient stores protocol 2
# state): an opening message of the old protocol carries the state itself, so it is handed to nbclient's store
# in the new protocol's shape. Updates ({"method": "update", "state": ...}) already have that shape.
_handle_comm_msg = nbclient.client.NotebookClient.handle_comm_msg


def _handle_comm_msg_storing_old_protocol(self, outs, msg, cell_index):
    data = msg["content"].get("data", {})
    if msg["msg_type"] == "comm_open" and "state" not in data and "_model_name" in data:
        msg["content"]["data"] = {"state": data, "buffer_paths": []}
    return _handle_comm_msg(self, outs, msg, cell_index)


nbclient.client.NotebookClient.handle_comm_msg = _handle_comm_msg_storing_old_protocol
