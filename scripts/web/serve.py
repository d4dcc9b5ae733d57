#!/usr/bin/env python3
"""Serves the web build's page on localhost: python3 serve.py DIR PORT (PORT 0: any free one).

Prints "Serving http://127.0.0.1:PORT/" once it listens. Any static server does (docs/web.md);
this one only makes sure that .wasm goes out as application/wasm (the browser then compiles it
while it downloads) and that nothing is cached between builds.
"""
import functools
import http.server
import sys


class Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {
        **http.server.SimpleHTTPRequestHandler.extensions_map,
        ".wasm": "application/wasm",
        ".js": "text/javascript",
        ".data": "application/octet-stream",
    }

    def end_headers(self):
        self.send_header("Cache-Control", "no-store")
        super().end_headers()

    def log_message(self, format, *args):  # quiet: the tests read the address line only
        pass


def main():
    directory, port = sys.argv[1], int(sys.argv[2])
    handler = functools.partial(Handler, directory=directory)
    with http.server.ThreadingHTTPServer(("127.0.0.1", port), handler) as server:
        print(f"Serving http://127.0.0.1:{server.server_address[1]}/", flush=True)
        server.serve_forever()


if __name__ == "__main__":
    main()
