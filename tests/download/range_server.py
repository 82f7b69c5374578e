#!/usr/bin/python3
"""A loopback file server for the download test: http.server with byte ranges (which
`python3 -m http.server` lacks, and `curl -C -` needs to resume), a request log, and
optionally a connection that breaks off after N bytes the first time each file is sent."""
import argparse
import http.server
import os
import re


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--root", required=True)
    parser.add_argument("--port-file", required=True, help="the chosen port is written here")
    parser.add_argument("--log", required=True, help="one line per request: path and Range")
    parser.add_argument("--drop-after", type=int, default=0,
                        help="break the first transfer of each file after this many bytes")
    args = parser.parse_args()
    dropped = set()

    class Handler(http.server.BaseHTTPRequestHandler):
        def log_message(self, *unused):
            pass

        def do_GET(self):
            path = os.path.join(args.root, self.path.lstrip("/"))
            with open(args.log, "a") as log:
                log.write("%s %s\n" % (self.path, self.headers.get("Range", "-")))
            if not os.path.isfile(path):
                self.send_error(404)
                return
            with open(path, "rb") as f:
                data = f.read()
            start = 0
            match = re.match(r"bytes=(\d+)-$", self.headers.get("Range", ""))
            if match:
                start = int(match.group(1))
                if start >= len(data):
                    self.send_response(416)
                    self.send_header("Content-Range", "bytes */%d" % len(data))
                    self.end_headers()
                    return
                self.send_response(206)
                self.send_header("Content-Range",
                                 "bytes %d-%d/%d" % (start, len(data) - 1, len(data)))
            else:
                self.send_response(200)
            self.send_header("Content-Length", str(len(data) - start))
            self.end_headers()
            body = data[start:]
            if args.drop_after and self.path not in dropped:
                dropped.add(self.path)
                self.wfile.write(body[:args.drop_after])
                self.wfile.flush()
                self.close_connection = True
                return
            self.wfile.write(body)

    server = http.server.HTTPServer(("127.0.0.1", 0), Handler)
    with open(args.port_file + ".tmp", "w") as f:
        f.write(str(server.server_address[1]))
    os.rename(args.port_file + ".tmp", args.port_file)
    server.serve_forever()


if __name__ == "__main__":
    main()
