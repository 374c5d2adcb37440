#!/usr/bin/env bash
# CI (issue 26): the online server's tests that need real outside programs.
#  - a real PostgreSQL from Debian's packages, in a private cluster on a loopback port, so the
#    database tests and a server round run on it (MINIGOLF_TEST_POSTGRES_URL);
#  - Debian's Chromium, headless, loading the server's web page (MINIGOLF_TEST_CHROMIUM).
# The same tests run in the main pass too, where they skip without these.
set -uo pipefail
cd "$(dirname "$0")/.."

sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
need=()
ls /usr/lib/postgresql/*/bin/initdb >/dev/null 2>&1 || need+=(postgresql)
command -v chromium >/dev/null || need+=(chromium)
if [ ${#need[@]} -gt 0 ]; then
    echo "online: installing ${need[*]}"
    $sudo apt-get update -qq || { echo "online: apt-get update failed"; exit 1; }
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null \
        || { echo "online: apt-get install ${need[*]} failed"; exit 1; }
fi

bin=$(ls -d /usr/lib/postgresql/*/bin | sort -V | tail -1)
work=$(mktemp -d)
chmod 755 "$work"
port=54326
as_pg() { if [ "$(id -u)" -eq 0 ]; then runuser -u postgres -- "$@"; else "$@"; fi; }
[ "$(id -u)" -eq 0 ] && chown postgres "$work"
stop_pg() { as_pg "$bin/pg_ctl" -D "$work/data" -m immediate stop >/dev/null 2>&1; rm -rf "$work"; }
trap stop_pg EXIT
as_pg "$bin/initdb" -D "$work/data" -A trust -U minigolf >/dev/null || { echo "online: initdb failed"; exit 1; }
as_pg "$bin/pg_ctl" -D "$work/data" -l "$work/pg.log" -w \
    -o "-p $port -k $work -c listen_addresses=127.0.0.1" start >/dev/null || { echo "online: PostgreSQL did not start"; cat "$work/pg.log"; exit 1; }
as_pg "$bin/createdb" -h 127.0.0.1 -p $port -U minigolf minigolf || { echo "online: createdb failed"; exit 1; }
echo "online: PostgreSQL $("$bin/postgres" --version | awk '{print $3}') on 127.0.0.1:$port"

export MINIGOLF_TEST_POSTGRES_URL="jdbc:postgresql://127.0.0.1:$port/minigolf?user=minigolf"
export MINIGOLF_TEST_CHROMIUM="$(command -v chromium)"
export MINIGOLF_TEST_REQUIRE=1   # here a missing PostgreSQL or browser fails the tests instead of skipping them
gradle --no-daemon --console=plain test --tests 'GameStoreTest' --tests 'PostgresServerTest' --tests 'WebPageBrowserTest' 2>&1 \
    | grep -E 'tests (successful|failed|skipped)|Failures|=>|BUILD' 
status=${PIPESTATUS[0]}
[ "$status" -eq 0 ] && echo "online: PostgreSQL and browser tests passed" || echo "online: PostgreSQL or browser tests failed"
exit "$status"
