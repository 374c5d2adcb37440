package minigolf.online.server;

/** One connected client as a room sees it: where messages go. Implemented by the WebSocket endpoint (and by tests). */
interface Client {
    /** Sends one message; never blocks (a client too slow to take its messages is disconnected). */
    void send(String json);

    /** Ends the connection with a WebSocket close code and reason. */
    void close(int code, String reason);

    /** The seat this connection now holds (called by the room, on its thread). */
    void seated(Room room, int seat);

    /** The remote address, for limits and logs. */
    String address();
}
