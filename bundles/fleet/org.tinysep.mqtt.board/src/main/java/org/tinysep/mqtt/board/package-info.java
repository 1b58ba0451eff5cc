/**
 * The central alert board: a care centre's view of many flats over MQTT (topic contract: {@code docs/mqtt.md}).
 * Everything lives in {@code org.tinysep.mqtt.board.internal}; the bundle exports nothing: its contract is the
 * MQTT topics it reads and the HTTP page and JSON it serves under {@code /board/}.
 */
package org.tinysep.mqtt.board;
